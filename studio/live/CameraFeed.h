#pragma once
// The Live view's camera: the frames of a QCamera (a QMediaCaptureSession into a QVideoSink), the
// newest kept for the live session's thread, which draws the generated face over it
// (render/CameraCompositor) instead of into the still of the person. Frames can also be handed in
// by code (setFrame: tests and demos without a camera). Only the newest frame is kept: a session
// draws each of its frames over the camera's picture of that moment, and memory does not grow.
#include <QObject>
#include <QString>

#include <opencv2/core.hpp>

#include <memory>
#include <mutex>

class QCamera;
class QCameraDevice;
class QImage;
class QMediaCaptureSession;
class QVideoFrame;
class QVideoSink;

namespace lipsync::studio {

class CameraFeed : public QObject
{
    Q_OBJECT
public:
    explicit CameraFeed(QObject *parent = nullptr);
    ~CameraFeed() override;

    // Starts `device` (one of QMediaDevices::videoInputs()); false, with `why`, when it cannot.
    bool open(const QCameraDevice &device, QString *why = nullptr);
    // Stops the camera and forgets its frames.
    void close();

    // The newest frame from any source (any thread may call these).
    void setFrame(const QImage &image);
    // A copy of the newest frame (8-bit BGR), empty before the first one.
    cv::Mat latest() const;

signals:
    // The camera stopped with an error (it was unplugged, or another program holds it).
    void failed(const QString &why);

private:
    void onVideoFrame(const QVideoFrame &frame);

    mutable std::mutex m_mutex;
    cv::Mat m_latest;
    std::unique_ptr<QCamera> m_camera;
    std::unique_ptr<QMediaCaptureSession> m_capture;
    QVideoSink *m_sink = nullptr;
};

} // namespace lipsync::studio
