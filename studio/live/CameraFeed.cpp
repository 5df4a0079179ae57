#include "live/CameraFeed.h"

#include <QCamera>
#include <QCameraDevice>
#include <QImage>
#include <QMediaCaptureSession>
#include <QVideoFrame>
#include <QVideoSink>

namespace lipsync::studio {

CameraFeed::CameraFeed(QObject *parent) : QObject(parent), m_sink(new QVideoSink(this))
{
    connect(m_sink, &QVideoSink::videoFrameChanged, this, &CameraFeed::onVideoFrame);
}

CameraFeed::~CameraFeed()
{
    close();
}

bool CameraFeed::open(const QCameraDevice &device, QString *why)
{
    close();
    if (device.isNull()) {
        if (why)
            *why = tr("No such camera.");
        return false;
    }
    m_camera = std::make_unique<QCamera>(device);
    m_capture = std::make_unique<QMediaCaptureSession>();
    m_capture->setCamera(m_camera.get());
    m_capture->setVideoSink(m_sink);
    connect(m_camera.get(), &QCamera::errorOccurred, this, [this](QCamera::Error error, const QString &text) {
        if (error != QCamera::NoError)
            emit failed(tr("The camera stopped: %1").arg(text));
    });
    m_camera->start();
    if (m_camera->error() != QCamera::NoError) {
        if (why)
            *why = tr("The camera %1 could not be opened: %2").arg(device.description(), m_camera->errorString());
        close();
        return false;
    }
    return true;
}

void CameraFeed::close()
{
    if (m_camera)
        m_camera->stop();
    if (m_capture)
        m_capture->setVideoSink(nullptr);
    m_capture.reset();
    m_camera.reset();
    const std::lock_guard lock(m_mutex);
    m_latest.release();
}

void CameraFeed::onVideoFrame(const QVideoFrame &frame)
{
    if (frame.isValid())
        setFrame(frame.toImage());
}

void CameraFeed::setFrame(const QImage &image)
{
    if (image.isNull())
        return;
    const QImage bgr = image.convertToFormat(QImage::Format_BGR888);
    const cv::Mat view(bgr.height(), bgr.width(), CV_8UC3, const_cast<uchar *>(bgr.constBits()),
                       size_t(bgr.bytesPerLine()));
    cv::Mat copy = view.clone();
    const std::lock_guard lock(m_mutex);
    m_latest = std::move(copy);
}

cv::Mat CameraFeed::latest() const
{
    const std::lock_guard lock(m_mutex);
    return m_latest.clone();
}

} // namespace lipsync::studio
