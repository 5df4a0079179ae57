#pragma once
// A microphone as the live session hears it: a Qt Multimedia QAudioSource on the chosen input
// device, in the format the session takes (mono float at its rate) when the device offers it,
// else 16-bit, else the device's preferred format converted (SampleConverter). Blocks of
// captured sound are announced as they arrive, on the GUI thread, with the time they arrived.
#include <QAudioDevice>
#include <QObject>
#include <QString>

#include <chrono>
#include <memory>
#include <vector>

class QAudioSource;
class QIODevice;

namespace lipsync::studio {

class SampleConverter;

class MicrophoneInput : public QObject
{
    Q_OBJECT
public:
    explicit MicrophoneInput(QObject *parent = nullptr);
    ~MicrophoneInput() override;

    // Starts capturing `device` at `sampleRate` (mono). Returns why it could not, or empty.
    QString start(const QAudioDevice &device, int sampleRate);
    void stop();
    bool isActive() const { return m_source != nullptr; }

signals:
    // Sound captured, mono float at the rate start() was given; `captured` is when it arrived.
    void captured(const std::vector<float> &samples, std::chrono::steady_clock::time_point captured);

private:
    void read();

    QAudioSource *m_source = nullptr;
    QIODevice *m_io = nullptr;
    std::unique_ptr<SampleConverter> m_converter;
};

} // namespace lipsync::studio
