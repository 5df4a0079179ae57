#pragma once
// Plays a sequence by stepping frames with a timer at the sequence's frame rate. Sound comes
// from Qt Multimedia (QMediaPlayer on the same file), started at the current frame's time.
// QMediaPlayer is not frame-accurate, so picture and sound may drift by a frame or two; the
// frame-locked player (own PCM through QAudioSink, frames following the audio clock) comes
// with the side-by-side preview of generated video.
#include <QObject>
#include <QString>

class QAudioOutput;
class QMediaPlayer;
class QTimer;

namespace lipsync::studio {

class PlaybackController : public QObject
{
    Q_OBJECT
public:
    explicit PlaybackController(QObject *parent = nullptr);

    void setSequence(const QString &mediaPath, int frameCount, double frameRate);
    bool isPlaying() const { return m_playing; }
    // Sound on/off (tests and screenshots run silent; the player is created on first use).
    void setAudioEnabled(bool enabled) { m_audioEnabled = enabled; }

public slots:
    void play(int fromFrame);
    void pause();

signals:
    void frameReached(int frame);
    void playingChanged(bool playing);

private:
    void tick();

    QTimer *m_timer;
    QMediaPlayer *m_player = nullptr;
    QAudioOutput *m_output = nullptr;
    QString m_mediaPath;
    int m_frameCount = 0;
    double m_frameRate = 25.0;
    int m_frame = 0;
    qint64 m_startMs = 0;
    int m_startFrame = 0;
    bool m_playing = false;
    bool m_audioEnabled = true;
};

} // namespace lipsync::studio
