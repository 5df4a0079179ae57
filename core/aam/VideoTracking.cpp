#include "aam/VideoTracking.h"

#include "aam/FaceDetector.h"
#include "aam/FaceTracker.h"
#include "aam/PtsFile.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace lipsync {

std::vector<int> VideoTrackingResult::worstFrames(int count) const
{
    std::vector<int> order;
    for (int i = 0; i < int(errors.size()); ++i)
        if (std::isfinite(errors[i]))
            order.push_back(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return errors[a] > errors[b]; });
    if (int(order.size()) > count)
        order.resize(size_t(std::max(0, count)));
    return order;
}

VideoTrackingResult trackVideo(const AamModel &model, const std::string &videoPath,
                               FaceDetector &detector, Feedback &feedback,
                               const std::map<int, LandmarkSet> &landmarks, int frames)
{
    VideoReader video(videoPath);
    const int n = frames > 0 ? std::min(frames, video.frameCount()) : video.frameCount();
    if (n <= 0)
        throw Error("the video holds no frames", videoPath);
    VideoTrackingResult result;
    result.frameRate = video.frameRate();
    result.features = Eigen::MatrixXd::Zero(n, model.combinedModes());
    result.shapes = Eigen::MatrixXd::Zero(n, 2 * model.pointCount());
    result.errors = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN());
    FaceTracker tracker(model, &detector);
    std::vector<bool> found(size_t(n), false);
    feedback.setStatus("tracking " + videoPath);
    for (int i = 0; i < n; ++i) {
        feedback.throwIfCanceled();
        feedback.setProgress(double(i) / n);
        const cv::Mat frame = video.frame(i);
        AamFitOptions options;
        if (auto it = landmarks.find(i); it != landmarks.end()) {
            // Points a user placed or corrected stay where they are (fixed points).
            options.fixedShape = shapeFromLandmarkSet(it->second);
            options.fixedMask.assign(size_t(model.pointCount()), false);
            for (int k = 0; k < model.pointCount() && k < LandmarkSet::kPointCount; ++k) {
                const PointState s = it->second.points[size_t(k)].state;
                options.fixedMask[size_t(k)] = s == PointState::Fixed || s == PointState::Placed;
            }
            if (std::none_of(options.fixedMask.begin(), options.fixedMask.end(), [](bool b) { return b; }))
                options = AamFitOptions{};
        }
        const auto t0 = std::chrono::steady_clock::now();
        const TrackedFrame t = tracker.track(frame, options);
        result.trackingSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!t.found)
            continue;
        found[size_t(i)] = true;
        result.redetections += t.redetected ? 1 : 0;
        result.features.row(i) = t.features.transpose();
        result.shapes.row(i) = t.fit.shape.transpose();
        result.errors[i] = t.fit.error;
    }
    // Frames without a face take the nearest tracked frame's parameters.
    std::vector<int> tracked;
    for (int i = 0; i < n; ++i)
        if (found[size_t(i)])
            tracked.push_back(i);
    if (tracked.empty())
        throw Error("no face found in any of the " + std::to_string(n) + " frames", videoPath);
    for (int i = 0; i < n; ++i) {
        if (found[size_t(i)])
            continue;
        result.framesWithoutFace.push_back(i);
        const auto it = std::lower_bound(tracked.begin(), tracked.end(), i);
        int nearest = it == tracked.end() ? tracked.back() : *it;
        if (it != tracked.begin() && (it == tracked.end() || i - *(it - 1) <= *it - i))
            nearest = *(it - 1);
        result.features.row(i) = result.features.row(nearest);
        result.shapes.row(i) = result.shapes.row(nearest);
    }
    feedback.setProgress(1.0);
    return result;
}

} // namespace lipsync
