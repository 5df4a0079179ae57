#include "live/LiveWorker.h"

#include "align/AcousticModel.h"
#include "align/PhoneBigram.h"
#include "dynamics/DynamicModel.h"
#include "live/CameraFeed.h"
#include "render/CameraCompositor.h"
#include "render/FaceRenderer.h"

#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <utility>

namespace lipsync::studio {

LiveWorker::LiveWorker(LiveSetup setup) : m_setup(std::move(setup)) {}

LiveWorker::~LiveWorker() = default;

void LiveWorker::begin()
{
    try {
        if (m_setup.sphinx)
            m_session = std::make_unique<LiveSession>(std::move(*m_setup.sphinx), *m_setup.model,
                                                      m_setup.renderer.get(), m_setup.options);
        else
            m_session = std::make_unique<LiveSession>(*m_setup.acoustic, *m_setup.bigram, *m_setup.model,
                                                      m_setup.renderer.get(), m_setup.options);
    } catch (const std::exception &e) {
        emit failed(QString::fromUtf8(e.what()));
        return;
    }
    emit started(m_session->frameRate(), m_session->latencySeconds());
}

void LiveWorker::push(const std::vector<float> &samples, Clock::time_point captured)
{
    if (!m_session || m_abandoned || samples.empty())
        return;
    try {
        std::vector<LiveFrame> ready = m_session->push(samples.data(), samples.size());
        if (!ready.empty())
            emit framesReady(collect(std::move(ready), m_session->soundSeconds(), captured, false));
    } catch (const std::exception &e) {
        m_session.reset();
        emit failed(QString::fromUtf8(e.what()));
    }
}

void LiveWorker::finish()
{
    if (!m_session || m_abandoned)
        return;
    try {
        std::vector<LiveFrame> ready = m_session->finish();
        emit framesReady(collect(std::move(ready), m_session->soundSeconds(), Clock::now(), true));
    } catch (const std::exception &e) {
        emit failed(QString::fromUtf8(e.what()));
    }
    m_session.reset();
}

void LiveWorker::drawOverCamera(LiveFrame &frame)
{
    cv::Mat picture = m_setup.camera && m_setup.aam ? m_setup.camera->latest() : cv::Mat();
    if (picture.empty())
        return;
    if (!m_camera)
        m_camera = std::make_unique<CameraCompositor>(*m_setup.aam);
    if (m_camera->compose(picture, frame.features, m_setup.renderer->compositeOptions()))
        frame.image = picture;
}

LiveFrames LiveWorker::collect(std::vector<LiveFrame> ready, double fed, Clock::time_point captured, bool last)
{
    LiveFrames out;
    for (LiveFrame &f : ready)
        drawOverCamera(f);
    const Clock::time_point drawn = Clock::now();
    const double sinceCapture = std::chrono::duration<double>(drawn - captured).count();
    for (LiveFrame &f : ready) {
        const cv::Mat &bgr = f.image;
        out.images.push_back(bgr.empty() ? QImage()
                                         : QImage(bgr.data, bgr.cols, bgr.rows, int(bgr.step), QImage::Format_BGR888)
                                               .copy());
        out.labels.push_back(f.label);
        out.features.push_back(std::move(f.features));
        // The frames Stop flushes waited for the end of the sound, not for the recogniser.
        out.latencies.push_back(last ? std::numeric_limits<double>::quiet_NaN() : sinceCapture + fed - f.soundEnd);
    }
    out.soundSeconds = fed;
    out.last = last;
    const std::vector<Interval> &all = m_session->phones().intervals;
    auto first = all.end();
    if (last)
        first = all.begin();
    else
        while (first != all.begin() && std::prev(first)->end > fed - kRecentPhoneSeconds)
            --first;
    out.phones.intervals.assign(first, all.end());
    return out;
}

} // namespace lipsync::studio
