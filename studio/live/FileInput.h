#pragma once
// A recording as the live session hears it, in place of a microphone: its sound (decoded up
// front, mono at the session's rate) handed out at the pace it plays, in blocks as a microphone
// would deliver them, while the file plays through the speakers so the user hears what the face
// says. Announces the end of the sound once all of it has been handed out.
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <chrono>
#include <memory>
#include <vector>

class QAudioOutput;
class QMediaPlayer;
class QTimer;

namespace lipsync::studio {

class FileInput : public QObject
{
    Q_OBJECT
public:
    // The longest file taken (the live recording keeps at most this much too).
    static constexpr double kMaxSeconds = 30 * 60;

    explicit FileInput(QObject *parent = nullptr);
    ~FileInput() override;

    // Starts handing out `sound` (mono at `sampleRate`) in real time and playing `path` aloud
    // (unless `audible` is false: tests, and machines without sound).
    void start(std::shared_ptr<const std::vector<float>> sound, int sampleRate, const QString &path, bool audible);
    void stop();
    bool isActive() const { return m_sound != nullptr; }

signals:
    // The next block of the file's sound, as if captured at `captured`.
    void captured(const std::vector<float> &samples, std::chrono::steady_clock::time_point captured);
    // All of the sound has been handed out.
    void ended();

private:
    void tick();

    std::shared_ptr<const std::vector<float>> m_sound;
    int m_sampleRate = 16000;
    std::size_t m_next = 0; // the first sample not handed out yet
    QElapsedTimer m_clock;
    QTimer *m_timer;
    QMediaPlayer *m_player = nullptr;
    QAudioOutput *m_output = nullptr;
};

} // namespace lipsync::studio
