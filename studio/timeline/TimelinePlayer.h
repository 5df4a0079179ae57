#pragma once
// Plays a stretch of the sequence's audio (the selection, one word, the whole sequence) through
// Qt Multimedia: QMediaPlayer on the media file, started at the stretch's start and stopped at
// its end. The position reported for the moving cursor follows the wall clock from the start
// (QMediaPlayer's own position is coarse), clamped to the stretch. Silent in batch mode (tests,
// screenshots): then only the cursor moves.
#include <QElapsedTimer>
#include <QObject>
#include <QString>

class QAudioOutput;
class QMediaPlayer;
class QTimer;

namespace lipsync::studio {

class TimelinePlayer : public QObject
{
    Q_OBJECT
public:
    explicit TimelinePlayer(QObject *parent = nullptr);

    void setMedia(const QString &mediaPath);
    bool isPlaying() const { return m_playing; }
    double position() const { return m_position; }
    void setAudioEnabled(bool enabled) { m_audioEnabled = enabled; }

public slots:
    void play(double from, double to);
    void stop();

signals:
    void positionChanged(double seconds);
    void playingChanged(bool playing);

private:
    void tick();

    QTimer *m_timer;
    QMediaPlayer *m_player = nullptr;
    QAudioOutput *m_output = nullptr;
    QString m_mediaPath;
    QElapsedTimer m_clock;
    double m_from = 0;
    double m_to = 0;
    double m_position = 0;
    bool m_playing = false;
    bool m_audioEnabled = true;
};

} // namespace lipsync::studio
