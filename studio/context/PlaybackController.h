#pragma once
// The studio's one player: plays the current sequence (or any stretch of it: the timeline's
// selection, one word, a loop) with its sound, and reports the position for the moving cursors
// of the timeline, the plots and the preview.
//
// Frame-locked to the audio clock: the sound is the media file's own PCM (core AudioDecoder)
// pushed through a Qt Multimedia QAudioSink, and the position is the audio the device has played
// (processed minus what still waits in its buffer), so the frame shown is the frame of the sound
// heard and the two cannot drift. Without sound (batch mode: tests, screenshots; no output
// device; a file without audio) the position follows a monotonic wall clock from the start.
#include "annotation/FrameClock.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <memory>

class QAudioSink;
class QBuffer;
class QTimer;

namespace lipsync {
struct AudioBuffer;
}

namespace lipsync::studio {

class PlaybackController : public QObject
{
    Q_OBJECT
public:
    explicit PlaybackController(QObject *parent = nullptr);
    ~PlaybackController() override;

    // What to play: the media (its audio is decoded on the first play with sound), when each of
    // its frames is shown (the media timeline, as the stream's timestamps say) and its length
    // (to the last frame's end, or `duration` seconds when given, e.g. audio only). Stops playback.
    void setSequence(const QString &mediaPath, const FrameClock &frames, double duration = -1.0);
    const QString &mediaPath() const { return m_mediaPath; }
    int frameCount() const { return m_frames.count(); }
    double frameRate() const { return m_frames.rate(); }
    const FrameClock &frames() const { return m_frames; }
    double duration() const { return m_duration; }

    bool isPlaying() const { return m_playing; }
    // Seconds from the start of the media: where playback is (or stopped).
    double position() const { return m_position; }
    // The stretch being (or last) played.
    double rangeStart() const { return m_from; }
    double rangeEnd() const { return m_to; }
    // Loop: at the end of the stretch, play it again (until paused).
    bool isLooping() const { return m_loop; }
    void setLooping(bool loop) { m_loop = loop; }
    // Sound on/off (tests and screenshots run silent).
    void setAudioEnabled(bool enabled) { m_audioEnabled = enabled; }
    // True while the position follows the audio device's clock.
    bool isAudioClocked() const { return m_sink != nullptr; }

public slots:
    // From a frame to the end (from the start when at the last frame).
    void play(int fromFrame);
    // The stretch [from, to] seconds.
    void playRange(double from, double to);
    void pause();
    void stop() { pause(); }

signals:
    // The video frame under the position changed; emitted before positionChanged.
    void frameReached(int frame);
    void positionChanged(double seconds);
    void playingChanged(bool playing);
    // Playback with sound on goes on without it (on the wall clock), and why: no output device,
    // a format it refuses, a clip without decodable sound, a device that stopped.
    void playingSilently(const QString &why);

private:
    void startRange(double from, double to, int fromFrame);
    void tick();
    void startClock();
    // Starts the sound of the range on the default output; empty, or why it cannot.
    QString startAudio();
    void stopAudio();
    double clockPosition() const;
    int frameAt(double seconds) const;

    QTimer *m_timer;
    QElapsedTimer m_wallClock;
    QAudioSink *m_sink = nullptr;
    QBuffer *m_pcm = nullptr;
    double m_bytesPerSecond = 0;
    std::shared_ptr<const AudioBuffer> m_audio; // decoded sound of m_mediaPath (null until needed)
    QString m_audioPath;                        // the file m_audio came from
    bool m_audioFailed = false;                 // decoding failed: play silent

    QString m_mediaPath;
    FrameClock m_frames;
    double m_duration = 0.0;
    double m_from = 0.0;
    double m_to = 0.0;
    double m_origin = 0.0; // media time at which the clock started
    double m_position = 0.0;
    int m_frame = -1;
    bool m_playing = false;
    bool m_loop = false;
    bool m_audioEnabled = true;
};

} // namespace lipsync::studio
