#include "aam/FramePicking.h"

#include "aam/AamBuilder.h"
#include "aam/AamFitter.h"
#include "aam/FaceDetector.h"
#include "aam/FrameSelection.h"
#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <algorithm>
#include <optional>

namespace lipsync {

namespace {

// Held-out folds of the review.
constexpr int kReviewFolds = 5;

// NME between each frame's automatic points and where an AAM built from the other frames, fitted
// from those points at the finest level, moves them: large for a misplaced point, or a face none
// of the other frames resembles. With fewer than 2 x kReviewFolds frames, one AAM of all of them
// judges.
void reviewPicks(std::vector<PickedFrame> &frames, std::vector<std::string> &warnings, Feedback &feedback)
{
    const int folds = int(frames.size()) >= 2 * kReviewFolds ? kReviewFolds : 1;
    AamBuildOptions build;
    build.referenceEyeDistance = 50; // placement, not texture detail, is judged: the small frame is enough
    build.levels = 1;
    build.maxExemplars = 0;
    AamFitOptions fit;
    fit.coarsestLevel = 0;
    for (int fold = 0; fold < folds; ++fold) {
        feedback.throwIfCanceled();
        feedback.setProgress(0.85 + 0.15 * double(fold) / folds);
        std::vector<AamTrainingExample> examples;
        for (size_t i = 0; i < frames.size(); ++i)
            if (folds == 1 || int(i) % folds != fold)
                examples.push_back({"frame " + std::to_string(frames[i].frame + 1), {}, frames[i].pixels.clone(),
                                    frames[i].shape});
        Feedback quiet;
        const AamModel model = buildAam(std::move(examples), build, quiet, &warnings);
        const AamFitter fitter(model);
        for (size_t i = 0; i < frames.size(); ++i)
            if (folds == 1 || int(i) % folds == fold)
                frames[i].disagreement =
                    normalisedMeanError(fitter.fit(frames[i].pixels, frames[i].shape, fit).shape, frames[i].shape);
    }
}

} // namespace

FramePicking pickFramesToLabel(const std::vector<std::string> &videos, const FramePickingOptions &options,
                               FaceDetector &detector, Feedback &feedback)
{
    if (!detector.hasYunet() && !detector.hasHaar())
        throw Error("no face detector available (YuNet model or Haar cascade)");
    FramePicking out;
    // 1. Candidates: every step-th frame of every clip with a confident face, described by its
    //    appearance. With dlib, the face is placed in the descriptor by its eye points and its
    //    mouth and jaw points join the descriptor; YuNet's keypoints alone are a few pixels off.
    struct Candidate
    {
        int source, frame;
        FaceDetection face;
    };
    std::vector<Candidate> candidates;
    std::vector<Eigen::VectorXd> descriptors;
    const int step = std::max(1, options.step);
    for (size_t s = 0; s < videos.size(); ++s) {
        feedback.setStatus("looking for faces in " + videos[s]);
        VideoReader video(videos[s]);
        for (int t = step / 2; t < video.frameCount(); t += step) {
            feedback.throwIfCanceled();
            const cv::Mat frame = video.frame(t);
            const std::vector<FaceDetection> faces = detector.detect(frame);
            if (faces.empty() || faces.front().score < FramePickingOptions::kMinScore)
                continue;
            Eigen::VectorXd points;
            if (detector.hasDlib()) {
                const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
                if (ibug.size() != 2 * scheme23::kIbugPointCount)
                    continue;
                points = mapIbug68To23(ibug);
            }
            candidates.push_back({int(s), t, faces.front()});
            descriptors.push_back(faceAppearanceDescriptor(frame, faces.front(), points));
        }
        feedback.setProgress(0.7 * double(s + 1) / double(videos.size()));
    }
    out.candidates = int(candidates.size());
    if (candidates.empty())
        throw Error("no face found in any candidate frame of the " + std::to_string(videos.size()) + " videos");
    Eigen::MatrixXd descriptorMatrix(descriptors.front().size(), Eigen::Index(descriptors.size()));
    for (size_t i = 0; i < descriptors.size(); ++i)
        descriptorMatrix.col(Eigen::Index(i)) = descriptors[i];
    std::vector<int> groups, excluded;
    for (const Candidate &c : candidates)
        groups.push_back(c.source);
    const DiverseSelection selection
        = selectDiverseFrames(descriptorMatrix, options.count, options.dimensions, groups, &excluded);
    for (int i : excluded)
        out.isolated.emplace_back(candidates[size_t(i)].source, candidates[size_t(i)].frame);

    // 2. The picks with their automatic points, clip by clip.
    std::vector<std::pair<size_t, double>> picks; // candidate, distance
    for (size_t k = 0; k < selection.picks.size(); ++k)
        picks.emplace_back(size_t(selection.picks[k]), selection.distances[k]);
    std::stable_sort(picks.begin(), picks.end(), [&](const auto &x, const auto &y) {
        return std::pair(candidates[x.first].source, candidates[x.first].frame)
               < std::pair(candidates[y.first].source, candidates[y.first].frame);
    });
    feedback.setStatus("placing the points");
    std::optional<VideoReader> video;
    std::optional<AamFitter> fitter; // one for every frame
    if (options.aam)
        fitter.emplace(*options.aam);
    for (size_t k = 0; k < picks.size(); ++k) {
        feedback.throwIfCanceled();
        const Candidate &c = candidates[picks[k].first];
        if (!video || video->path() != videos[size_t(c.source)])
            video.emplace(videos[size_t(c.source)]);
        PickedFrame f;
        f.source = c.source;
        f.frame = c.frame;
        f.distance = picks[k].second;
        f.pixels = video->frame(c.frame);
        const AutoLandmarks points =
            detectAutoLandmarks(f.pixels, c.face, detector, options.method, fitter ? &*fitter : nullptr);
        f.shape = points.shape;
        f.method = points.method;
        out.frames.push_back(std::move(f));
        feedback.setProgress(0.7 + 0.15 * double(k + 1) / double(picks.size()));
    }

    // 3. Review order.
    if (options.review && out.frames.size() >= 3) {
        feedback.setStatus("ranking the picks for review");
        reviewPicks(out.frames, out.warnings, feedback);
    }
    for (size_t i = 0; i < out.frames.size(); ++i)
        out.worstFirst.push_back(int(i));
    std::stable_sort(out.worstFirst.begin(), out.worstFirst.end(), [&](int x, int y) {
        return out.frames[size_t(x)].disagreement > out.frames[size_t(y)].disagreement;
    });
    feedback.setProgress(1.0);
    return out;
}

} // namespace lipsync
