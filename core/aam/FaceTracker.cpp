#include "aam/FaceTracker.h"

#include "aam/FaceDetector.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <vector>

namespace lipsync {

FaceTracker::FaceTracker(const AamModel &model, FaceDetector *detector, FaceTrackerOptions options)
    : m_fitter(model), m_detector(detector), m_options(options)
{
}

void FaceTracker::setShape(const Eigen::VectorXd &shape)
{
    m_previous = shape;
}

void FaceTracker::reset()
{
    m_previous.resize(0);
    m_errors.clear();
}

double FaceTracker::medianError() const
{
    if (m_errors.empty())
        return 0.0;
    std::vector<double> v(m_errors.begin(), m_errors.end());
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

bool FaceTracker::fitFromDetection(const cv::Mat &bgr, const cv::Mat &grey,
                                   const AamFitOptions &options, AamFitResult &out)
{
    if (!m_detector)
        return false;
    const std::vector<FaceDetection> faces = m_detector->detect(bgr);
    if (faces.empty())
        return false;
    const Eigen::VectorXd start = initialShapeFromDetection(m_fitter.model(), faces.front());
    AamFitOptions full = options;
    full.coarsestLevel = -1;
    out = m_fitter.fit(grey, start, full);
    return true;
}

TrackedFrame FaceTracker::track(const cv::Mat &bgr, const AamFitOptions &fitOptions)
{
    TrackedFrame frame;
    const cv::Mat grey = greyFloat(bgr);

    if (m_previous.size() == 0) {
        if (!fitFromDetection(bgr, grey, fitOptions, frame.fit))
            return frame;
        frame.redetected = true;
    } else {
        AamFitOptions options = fitOptions;
        if (m_options.fineLevelOnly)
            options.coarsestLevel = 0;
        frame.fit = m_fitter.fit(grey, m_previous, options);
        const double median = medianError();
        // Re-detect when the error jumps above the recent ones, and keep trying while the
        // recent fits are all poor (a track started on a broken frame must not lock in).
        const bool jumped = frame.fit.error > m_options.minRedetectError
                            && (m_errors.empty() || frame.fit.error > m_options.redetectFactor * median
                                || median > m_options.minRedetectError);
        if (jumped) {
            AamFitResult again;
            if (fitFromDetection(bgr, grey, fitOptions, again) && again.error < frame.fit.error) {
                frame.fit = again;
                frame.redetected = true;
            }
        }
    }
    frame.found = true;
    m_previous = frame.fit.shape;
    m_errors.push_back(frame.fit.error);
    while (int(m_errors.size()) > m_options.historyLength)
        m_errors.pop_front();
    frame.features = m_fitter.features(bgr, frame.fit);
    return frame;
}

} // namespace lipsync
