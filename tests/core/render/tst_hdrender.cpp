// Rendering into HD footage of another person with a moving head (tests/data/media/hd: a White
// House weekly address, 1280x720, public domain): an AAM built from the clip's own frames (dlib's
// points), the face tracked, and every frame rendered with its mouth opened further than
// recorded. The recording keeps its own face: at every pose the render differs from the recording
// only inside the warped region, the region's border shows no step beyond the recording's own
// (the warp fades to nothing there), and the eyes are the recording's. And the mouth goes where
// it is asked: an open mouth asked to close is closed in the render, as dlib's landmarker reads it
// (at HD scale the spline's system must be solved well, or nothing moves), with his own closed
// lips from another moment of the clip; a mouth asked to open opens most of the way, and shows his
// own teeth; and nothing flickers from frame to frame.
#include "aam/AamBuilder.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "render/BilabialClosure.h"
#include "render/MouthExemplars.h"
#include "render/FaceRenderer.h"
#include "render/LowerFaceWarp.h"
#include "tasks/Feedback.h"

#include <opencv2/imgproc.hpp>

#include <QTest>

#include <cmath>
#include <map>
#include <memory>

using namespace lipsync;

namespace {
const std::string kClip = LIPSYNC_SOURCE_DIR "/tests/data/media/hd/obama_weekly_address_library.mp4";

// The mean colour (CIELAB, 8-bit) and texture (the Laplacian's spread) of frames within an outline.
struct Look
{
    cv::Vec3d lab{0, 0, 0};
    double sharpness = 0;
    int count = 0;
    void add(const cv::Mat &frame, const std::vector<cv::Point2f> &within)
    {
        std::vector<cv::Point> outline;
        for (const cv::Point2f &p : within)
            outline.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
        cv::Mat mask(frame.size(), CV_8U, cv::Scalar(0));
        cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(255));
        cv::erode(mask, mask, cv::Mat(), cv::Point(-1, -1), 2); // off the outline's edge
        cv::Mat labImage, grey, laplacian;
        cv::cvtColor(frame, labImage, cv::COLOR_BGR2Lab);
        cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
        cv::Laplacian(grey, laplacian, CV_64F);
        const cv::Scalar m = cv::mean(labImage, mask);
        cv::Scalar mean, sd;
        cv::meanStdDev(laplacian, mean, sd, mask);
        lab += cv::Vec3d(m[0], m[1], m[2]);
        sharpness += sd[0];
        ++count;
    }
    cv::Vec3d meanLab() const { return lab / std::max(1, count); }
    double meanSharpness() const { return sharpness / std::max(1, count); }
};

// dlib's inner-lip gap (iBUG 61-67, 62-66, 63-65) in pixels; NaN where it finds no face.
double dlibGap(FaceDetector &detector, const cv::Mat &frame)
{
    const std::vector<FaceDetection> faces = detector.detect(frame);
    const Eigen::VectorXd p = faces.empty() ? Eigen::VectorXd() : detector.dlibLandmarks(frame, faces.front());
    if (p.size() != 136)
        return NAN;
    double sum = 0;
    for (const auto &[a, b] : {std::pair{61, 67}, std::pair{62, 66}, std::pair{63, 65}})
        sum += std::hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]);
    return sum / 3.0;
}

// Logs the looks of what the recording shows, his own mouths drawn in and the AAM's; returns the
// colour distance of his own to the recording's.
double compare(const char *what, const Look &recorded, const Look &own, const Look &drawn)
{
    const double ownDistance = cv::norm(own.meanLab() - recorded.meanLab());
    const double drawnDistance = cv::norm(drawn.meanLab() - recorded.meanLab());
    qInfo("%s, CIELAB (8-bit) and Laplacian s.d.: recorded %.1f %.1f %.1f, %.1f (%d frames); his own drawn in %.1f "
          "%.1f %.1f, %.1f (%d frames, %.1f from the recorded); the AAM's %.1f %.1f %.1f, %.1f (%.1f from the recorded)",
          what, recorded.meanLab()[0], recorded.meanLab()[1], recorded.meanLab()[2], recorded.meanSharpness(),
          recorded.count, own.meanLab()[0], own.meanLab()[1], own.meanLab()[2], own.meanSharpness(), own.count,
          ownDistance, drawn.meanLab()[0], drawn.meanLab()[1], drawn.meanLab()[2], drawn.meanSharpness(), drawnDistance);
    return ownDistance;
}
} // namespace

class TestHdRender : public QObject
{
    Q_OBJECT

    AamModel m_aam;
    // The clip's face tracked once with m_aam, shared by every test (each starts from its default
    // compositing, init()).
    std::unique_ptr<FaceRenderer> m_renderer;
    CompositeOptions m_defaults;

private slots:
    void initTestCase()
    {
        FaceDetector detector;
        if (!detector.hasDlib())
            QSKIP("dlib's 68-point predictor is not installed (libdlib-data)");
        VideoReader video(kClip);
        QCOMPARE(video.width(), 1280);
        std::vector<AamTrainingExample> examples;
        for (int t = 0; t < video.frameCount(); t += 4) {
            const cv::Mat frame = video.frame(t);
            const std::vector<FaceDetection> faces = detector.detect(frame);
            if (faces.empty())
                continue;
            const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
            if (ibug.size() == 136)
                examples.push_back({"frame" + std::to_string(t), {}, frame, mapIbug68To23(ibug)});
        }
        QVERIFY2(examples.size() >= 20, qPrintable(QString::number(examples.size())));
        Feedback feedback;
        m_aam = buildAam(examples, {}, feedback);
        QVERIFY(m_aam.combinedModes() > 2);
        m_renderer = std::make_unique<FaceRenderer>(m_aam, kClip, feedback);
        m_defaults = m_renderer->compositeOptions();
    }

    void init()
    {
        if (m_renderer)
            m_renderer->setCompositeOptions(m_defaults);
    }

    void movingHeadWithoutEdges()
    {
        FaceRenderer &renderer = *m_renderer;
        const int frames = renderer.videoFrameCount();
        QVERIFY(frames > 100);
        // The head moves in this clip: its pose turns and shifts across the frames.
        double angleMin = 1e9, angleMax = -1e9, xMin = 1e9, xMax = -1e9;
        for (int t = 0; t < frames; ++t) {
            const Similarity &p = renderer.pose(t);
            angleMin = std::min(angleMin, std::atan2(p.b, p.a));
            angleMax = std::max(angleMax, std::atan2(p.b, p.a));
            xMin = std::min(xMin, p.tx);
            xMax = std::max(xMax, p.tx);
        }
        qInfo("head roll %.1f..%.1f degrees, face centre x %.0f..%.0f px", angleMin * 180 / M_PI, angleMax * 180 / M_PI,
              xMin, xMax);
        QVERIFY(angleMax - angleMin > 2.0 * M_PI / 180 || xMax - xMin > 10.0);
        double worstStep = 0;
        int warped = 0;
        for (int t = 0; t < frames; t += 3) {
            const cv::Mat recorded = renderer.background(t);
            // The tracked parameters with the first combined mode moved by 2 s.d.: a different
            // mouth and jaw at the recorded pose.
            Eigen::VectorXd c = renderer.trackedFeatures().row(t).transpose();
            c[0] += 2.0 * std::sqrt(m_aam.combinedVariances[0]);
            const cv::Mat rendered = renderer.render(t, c);
            cv::Mat diff, grey;
            cv::absdiff(rendered, recorded, diff);
            cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
            const cv::Rect changed = cv::boundingRect(grey > 0);
            if (changed.empty())
                continue;
            ++warped;
            // The changed region stays around the face (not the whole frame)...
            QVERIFY2(changed.area() < 1280 * 720 / 3, qPrintable(QString("frame %1: %2 px").arg(t).arg(changed.area())));
            // ...and fades in from nothing: across its border (each outermost changed pixel and its
            // unchanged neighbour outside) the render steps no more than the recording does there.
            auto excessStep = [&](const cv::Point &in, const cv::Point &out) {
                if (!cv::Rect(0, 0, grey.cols, grey.rows).contains(out))
                    return 0.0;
                auto luma = [](const cv::Mat &m, const cv::Point &q) {
                    const cv::Vec3b v = m.at<cv::Vec3b>(q);
                    return 0.114 * v[0] + 0.587 * v[1] + 0.299 * v[2];
                };
                return std::abs(luma(rendered, in) - luma(rendered, out)) - std::abs(luma(recorded, in) - luma(recorded, out));
            };
            double step = 0;
            for (int x = changed.x; x < changed.x + changed.width; ++x) {
                step = std::max(step, excessStep({x, changed.y}, {x, changed.y - 1}));
                step = std::max(step, excessStep({x, changed.y + changed.height - 1}, {x, changed.y + changed.height}));
            }
            for (int y = changed.y; y < changed.y + changed.height; ++y) {
                step = std::max(step, excessStep({changed.x, y}, {changed.x - 1, y}));
                step = std::max(step, excessStep({changed.x + changed.width - 1, y}, {changed.x + changed.width, y}));
            }
            worstStep = std::max(worstStep, step);
            // The eyes are the recording's.
            const Eigen::VectorXd points = renderer.trackedShape(t);
            for (int k = 0; k < 8; ++k) {
                const cv::Point p(int(std::lround(points[2 * k])), int(std::lround(points[2 * k + 1])));
                QVERIFY2(grey.at<uchar>(p) <= 4, qPrintable(QString("frame %1, eye point %2: %3").arg(t).arg(k).arg(grey.at<uchar>(p))));
            }
        }
        qInfo("%d frames warped; largest step across the warped region's border beyond the recording's own: "
              "%.1f levels", warped, worstStep);
        QVERIFY(warped > frames / 6);
        // Within 8-bit rounding of the pixels either side (a level or so each).
        QVERIFY2(worstStep <= 3.0, qPrintable(QString::number(worstStep)));
    }

    // Every fourth frame whose mouth is open, drawn shut by the /p b m/ closure: dlib reads the
    // lips' gap at under half the recorded one in three of four or more.
    void openMouthAskedToCloseCloses()
    {
        FaceDetector detector;
        FaceRenderer &renderer = *m_renderer;
        const BilabialClosure closure(m_aam);
        auto gap = [&](const cv::Mat &frame) { return dlibGap(detector, frame); };
        int open = 0, closed = 0;
        for (int t = 0; t < renderer.videoFrameCount(); t += 4) {
            if (LowerFaceWarp::opening(renderer.trackedShape(t)) < 12.0)
                continue; // open mouths only
            const cv::Mat recorded = renderer.background(t);
            const Eigen::MatrixXd shut
                = closure.apply(renderer.trackedFeatures().row(t), std::vector<double>{1.0});
            const double before = gap(recorded), after = gap(renderer.render(t, shut.row(0).transpose()));
            if (!std::isfinite(before) || !std::isfinite(after) || before < 8.0)
                continue;
            ++open;
            closed += after < 0.5 * before;
        }
        qInfo("%d of %d open mouths closed in the render (dlib's gap under half the recorded one)", closed, open);
        QVERIFY(open >= 5);
        QVERIFY2(closed >= open * 3 / 4, qPrintable(QStringLiteral("%1 of %2").arg(closed).arg(open)));
    }

    // A mouth asked to close closes about the eyes, as his own does: the generated shape is laid
    // on the tracked face by its eye corners (FaceRenderer::drawnPose), which stay where the
    // recording has them, and of each pixel the lips close the upper lip takes the share his own
    // recorded mouth gives it (the slope of its height on the opening, in eye-line coordinates).
    // Placed at the tracked face's pose, the model's shape (aligned on all its points) puts its
    // eyes lower and lets the upper lip take more: the nose is drawn down with it.
    void mouthClosesAboutTheEyes()
    {
        FaceRenderer &renderer = *m_renderer;
        const BilabialClosure closure(m_aam);
        // Heights below the eyes' midpoint of `eyes` (the recording's, which the render keeps) along
        // the face's vertical, in eye-corner distances.
        auto height = [](const Eigen::VectorXd &shape, int point, const Eigen::VectorXd &eyes) {
            const Eigen::Vector2d left = eyes.segment<2>(2 * scheme23::kLeftEyeOuter);
            const Eigen::Vector2d right = eyes.segment<2>(2 * scheme23::kRightEyeOuter);
            const Eigen::Vector2d across = right - left;
            const Eigen::Vector2d down(-across.y(), across.x());
            return (shape.segment<2>(2 * point) - 0.5 * (left + right)).dot(down) / across.squaredNorm();
        };
        constexpr int kUpperLip = 16, kLowerLip = 17; // inner-lip centres
        auto opening = [&](const Eigen::VectorXd &shape, const Eigen::VectorXd &eyes) {
            return height(shape, kLowerLip, eyes) - height(shape, kUpperLip, eyes);
        };
        // His own: the upper lip's height against the opening over the recorded frames.
        double so = 0, su = 0, soo = 0, sou = 0;
        const int frames = renderer.videoFrameCount();
        for (int t = 0; t < frames; ++t) {
            const Eigen::VectorXd shape = renderer.trackedShape(t);
            const double o = opening(shape, shape), u = height(shape, kUpperLip, shape);
            so += o, su += u, soo += o * o, sou += o * u;
        }
        const double recorded = (sou - so * su / frames) / (soo - so * so / frames);
        double closedBy = 0, upperDrawn = 0, upperAtPose = 0, eyes = 0, eyesAtPose = 0;
        int asked = 0;
        for (int t = 0; t < frames; t += 3) {
            const Eigen::VectorXd tracked = renderer.trackedShape(t);
            if (LowerFaceWarp::opening(tracked) < 12.0)
                continue; // open mouths only
            const Eigen::VectorXd shut = closure.apply(renderer.trackedFeatures().row(t), std::vector<double>{1.0}).row(0).transpose();
            const Eigen::VectorXd drawn = renderer.drawnShape(t, shut);
            const Eigen::VectorXd atPose = renderer.pose(t).apply(renderer.synthesizer().shape(shut));
            for (int corner : scheme23::kEyeCorners) {
                eyes += (drawn.segment<2>(2 * corner) - tracked.segment<2>(2 * corner)).norm();
                eyesAtPose += (atPose.segment<2>(2 * corner) - tracked.segment<2>(2 * corner)).norm();
            }
            closedBy += opening(tracked, tracked) - opening(drawn, tracked);
            upperDrawn += height(drawn, kUpperLip, tracked) - height(tracked, kUpperLip, tracked);
            upperAtPose += height(atPose, kUpperLip, tracked) - height(tracked, kUpperLip, tracked);
            ++asked;
        }
        QVERIFY(asked >= 10);
        eyes /= 4 * asked;
        eyesAtPose /= 4 * asked;
        // Shares of the closing the upper lip takes (a lowered upper lip closes: the slope's sign flipped).
        const double drawnShare = upperDrawn / closedBy, atPoseShare = upperAtPose / closedBy;
        qInfo("%d open mouths closed: eye corners moved %.2f px (%.2f px at the tracked pose); upper lip's share "
              "%.2f (%.2f at the tracked pose), his own %.2f",
              asked, eyes, eyesAtPose, drawnShare, atPoseShare, -recorded);
        QVERIFY2(eyes < 0.5 && eyes < 0.25 * eyesAtPose, qPrintable(QString::number(eyes)));
        QVERIFY2(std::abs(drawnShare + recorded) < 0.1, qPrintable(QString::number(drawnShare)));
        QVERIFY(std::abs(drawnShare + recorded) < std::abs(atPoseShare + recorded));
    }

    // The other way: each frame drawn with the mouth of the frame half the clip away (new speech
    // in his own video), where that mouth is open wider, opens most of the way to that frame's, as
    // dlib reads both: the warp may stretch the thin line between the lips as far as asked (his own
    // inside is drawn over it), and his own inside weighs fully where the recording lacks a third
    // of the opening (0.70 of the opening asked is reached; with a warp that stretched at most
    // fourfold and an inside weighted by the whole shortfall, 0.57).
    void closedMouthAskedToOpenOpens()
    {
        FaceDetector detector;
        FaceRenderer &renderer = *m_renderer;
        const int frames = renderer.videoFrameCount();
        std::map<int, double> gaps; // dlib's gap of the recorded frames asked about
        auto recorded = [&](int t) {
            const auto [it, added] = gaps.try_emplace(t, NAN);
            if (added)
                it->second = dlibGap(detector, renderer.background(t));
            return it->second;
        };
        double wanted = 0, achieved = 0;
        int asked = 0;
        for (int t = 0; t < frames; t += 2) {
            const int away = (t + frames / 2) % frames;
            const double before = recorded(t), target = recorded(away);
            if (!std::isfinite(before) || !std::isfinite(target) || target < before + 4.0)
                continue; // mouths asked to open by 4 pixels or more
            const double after = dlibGap(detector, renderer.render(t, renderer.trackedFeatures().row(away).transpose()));
            if (!std::isfinite(after))
                continue;
            ++asked;
            wanted += target - before;
            achieved += after - before;
        }
        qInfo("%d mouths asked to open: %.2f of the opening asked reached (dlib's gap)", asked, achieved / wanted);
        QVERIFY(asked >= 10);
        QVERIFY2(achieved > 0.65 * wanted, qPrintable(QString::number(achieved / wanted)));
    }

    // No flicker: rendered through the clip with another mouth, closed over two runs of frames
    // (his own closed lips drawn in), the mouth changes from frame to frame about as much as the
    // recording's does, at the warped region's border and inside the mouth alike.
    void steadyOverTime()
    {
        FaceRenderer &renderer = *m_renderer;
        const int frames = renderer.videoFrameCount();
        Eigen::MatrixXd trajectory = renderer.trackedFeatures().topRows(frames);
        trajectory.col(0).array() += 2.0 * std::sqrt(m_aam.combinedVariances[0]);
        std::vector<double> closed(size_t(frames), 0.0);
        for (int t = 0; t < frames; ++t)
            closed[size_t(t)] = (t >= 30 && t < 45) || (t >= 70 && t < 85) ? 1.0 : 0.0;
        trajectory = BilabialClosure(m_aam).apply(trajectory, closed);
        cv::Mat previousRendered, previousRecorded;
        double mouthRendered = 0, mouthRecorded = 0, worstExcess = 0;
        int pairs = 0;
        for (int t = 0; t < frames; ++t) {
            const cv::Mat recorded = renderer.background(t);
            const cv::Mat rendered = renderer.render(t, trajectory.row(t).transpose());
            cv::Mat greyRendered, greyRecorded;
            cv::cvtColor(rendered, greyRendered, cv::COLOR_BGR2GRAY);
            cv::cvtColor(recorded, greyRecorded, cv::COLOR_BGR2GRAY);
            if (t > 0) {
                // The mouth and its surroundings: the tracked outer lips grown by half the mouth's width.
                const Eigen::VectorXd shape = renderer.trackedShape(t);
                const cv::Rect box = cv::boundingRect(LowerFaceWarp::outerLips(shape, 0.5 * LowerFaceWarp::mouthWidth(shape)))
                                     & cv::Rect(0, 0, rendered.cols, rendered.rows);
                cv::Mat a, b;
                cv::absdiff(greyRendered(box), previousRendered(box), a);
                cv::absdiff(greyRecorded(box), previousRecorded(box), b);
                const double changeRendered = cv::mean(a)[0], changeRecorded = cv::mean(b)[0];
                mouthRendered += changeRendered;
                mouthRecorded += changeRecorded;
                // Not where the closure asked of it starts or ends: the mouth is meant to move there.
                if (closed[size_t(t)] == closed[size_t(t - 1)])
                    worstExcess = std::max(worstExcess, changeRendered - changeRecorded);
                ++pairs;
            }
            previousRendered = greyRendered;
            previousRecorded = greyRecorded;
        }
        qInfo("mean change of the mouth's box from frame to frame: rendered %.2f, recorded %.2f levels; the largest "
              "excess of one frame over the recording's, away from the closures' start and end: %.2f levels (%d "
              "frame pairs)",
              mouthRendered / pairs, mouthRecorded / pairs, worstExcess, pairs);
        QVERIFY(pairs > 100);
        QVERIFY2(mouthRendered < 1.15 * mouthRecorded, qPrintable(QString::number(mouthRendered / mouthRecorded)));
        QVERIFY2(worstExcess < 3.0, qPrintable(QString::number(worstExcess)));
    }

    // The closed lips drawn over open ones are his own: their colour (CIELAB, inside the lips'
    // outline) and their texture (the Laplacian's spread there) are those of the lips he closes
    // in the recording; the AAM's synthesis of closed lips (an average over open and closed
    // training frames, with its exemplar detail) has more than twice the recorded texture.
    void closedLipsAreHisOwn()
    {
        FaceRenderer &renderer = *m_renderer;
        const BilabialClosure closure(m_aam);
        QVERIFY(!renderer.mouths().empty()); // the clip has closed lips of its own
        Look recorded, own, drawn;
        CompositeOptions aamClosures = renderer.compositeOptions();
        aamClosures.recordedClosures = false;
        for (int t = 0; t < renderer.videoFrameCount(); ++t) {
            const Eigen::VectorXd shape = renderer.trackedShape(t);
            const double share = MouthExemplars::openingShare(shape);
            if (share < MouthExemplars::kClosedShare) {
                recorded.add(renderer.background(t), LowerFaceWarp::outerLips(shape, 0.0));
                continue;
            }
            if (share < 0.15 || t % 2)
                continue; // open mouths asked to close, every other frame
            const Eigen::VectorXd shut = closure.apply(renderer.trackedFeatures().row(t), std::vector<double>{1.0}).row(0).transpose();
            const Eigen::VectorXd generated = renderer.drawnShape(t, shut);
            own.add(renderer.render(t, shut), LowerFaceWarp::outerLips(generated, 0.0));
            bool inside = true, closing = false;
            renderer.synthesisedWeight(t, shut, &inside, &closing);
            QVERIFY(!inside && closing); // closed lips, not an inside
            cv::Mat frame = renderer.background(t);
            renderer.renderInto(t, shut, frame, aamClosures);
            drawn.add(frame, LowerFaceWarp::outerLips(generated, 0.0));
        }
        // The clip closes its lips in four frames of its own (a precondition, not a measure).
        QVERIFY2(recorded.count >= 4 && own.count >= 5, qPrintable(QStringLiteral("%1 recorded, %2 own").arg(recorded.count).arg(own.count)));
        const double ownDistance = compare("closed lips", recorded, own, drawn);
        // Within a few CIELAB units of his own (both are colour-matched to the skin around them)...
        QVERIFY2(ownDistance < 3.0, qPrintable(QString::number(ownDistance)));
        // ... and as sharp as his own, where the AAM's closed lips carry the lines of an average.
        QVERIFY(std::abs(own.meanSharpness() - recorded.meanSharpness())
                < std::abs(drawn.meanSharpness() - recorded.meanSharpness()));
    }

    // The inside of a mouth opened wider than recorded is his own: nearly closed mouths asked to
    // open as wide as his widest, their inside (within the generated inner lips) has the texture
    // of the widest mouths he makes in the recording; the AAM's inside, an average over its
    // training frames sampled in a reference frame smaller than his face, is far smoother.
    void openMouthsAreHisOwn()
    {
        FaceRenderer &renderer = *m_renderer;
        QVERIFY(!renderer.mouths().openFrames().empty());
        int widest = 0;
        for (int t = 0; t < renderer.videoFrameCount(); ++t)
            if (MouthExemplars::openingShare(renderer.trackedShape(t)) > MouthExemplars::openingShare(renderer.trackedShape(widest)))
                widest = t;
        const Eigen::VectorXd wide = renderer.trackedFeatures().row(widest).transpose();
        const double widestShare = MouthExemplars::openingShare(renderer.trackedShape(widest));
        Look recorded, own, drawn;
        CompositeOptions aamInsides = renderer.compositeOptions();
        aamInsides.recordedInsides = false;
        for (int t = 0; t < renderer.videoFrameCount(); ++t) {
            const Eigen::VectorXd shape = renderer.trackedShape(t);
            const double share = MouthExemplars::openingShare(shape);
            if (MouthExemplars::bandOf(share) >= MouthExemplars::bandOf(widestShare) - 2) {
                recorded.add(renderer.background(t), LowerFaceWarp::mouthInterior(shape));
                continue;
            }
            if (share > 0.1 || t % 2)
                continue; // nearly closed mouths asked to open, every other frame
            const Eigen::VectorXd generated = renderer.drawnShape(t, wide);
            own.add(renderer.render(t, wide), LowerFaceWarp::mouthInterior(generated));
            bool inside = false, closing = true;
            renderer.synthesisedWeight(t, wide, &inside, &closing);
            QVERIFY(inside && !closing);
            cv::Mat frame = renderer.background(t);
            renderer.renderInto(t, wide, frame, aamInsides);
            drawn.add(frame, LowerFaceWarp::mouthInterior(generated));
        }
        QVERIFY2(recorded.count >= 5 && own.count >= 5, qPrintable(QStringLiteral("%1 recorded, %2 own").arg(recorded.count).arg(own.count)));
        // A synthesised face is no inside, however wide its mouth.
        CompositeOptions fullFace = renderer.compositeOptions();
        fullFace.region = FaceRegion::Full;
        renderer.setCompositeOptions(fullFace);
        bool inside = true;
        QVERIFY(cv::countNonZero(renderer.synthesisedWeight(widest, wide, &inside)) > 0);
        QVERIFY(!inside);
        const double ownDistance = compare("open mouths' insides", recorded, own, drawn);
        // His own teeth and inside: the texture of his open mouths, within a quarter (the AAM's has
        // under half of it)...
        QVERIFY2(std::abs(own.meanSharpness() / recorded.meanSharpness() - 1.0) < 0.25,
                 qPrintable(QString::number(own.meanSharpness() / recorded.meanSharpness())));
        QVERIFY(drawn.meanSharpness() < 0.5 * recorded.meanSharpness());
        // ... and their colour, within what teeth showing more or less moves it (an inside from a
        // narrower mouth, stretched, shows more of its teeth: 12 CIELAB units lighter here).
        QVERIFY2(ownDistance < 15.0, qPrintable(QString::number(ownDistance)));
    }

    // Where the lips meet, the drawn inside gives way to his own lips moved apart: nearly closed
    // mouths asked to open as wide as his widest, the inside is drawn fully midway between the
    // corners and fades to nothing toward them (a tracked corner a few pixels off the visible one
    // would otherwise put the inside's dark tip on his lips).
    void insideFadesAtTheCorners()
    {
        using namespace scheme23;
        FaceRenderer &renderer = *m_renderer;
        int widest = 0;
        for (int t = 0; t < renderer.videoFrameCount(); ++t)
            if (MouthExemplars::openingShare(renderer.trackedShape(t)) > MouthExemplars::openingShare(renderer.trackedShape(widest)))
                widest = t;
        const Eigen::VectorXd wide = renderer.trackedFeatures().row(widest).transpose();
        int checked = 0;
        for (int t = 0; t < renderer.videoFrameCount(); t += 3) {
            if (MouthExemplars::openingShare(renderer.trackedShape(t)) > 0.1)
                continue;
            const Eigen::VectorXd shape = renderer.warpedShape(t, wide);
            const cv::Mat weight = renderer.synthesisedWeight(t, wide);
            // Points on the line midway between the generated inner lips, from corner to corner.
            const Eigen::Vector2d left = shape.segment<2>(2 * kMouthLeft), right = shape.segment<2>(2 * kMouthRight);
            const Eigen::Vector2d middle = 0.5 * (shape.segment<2>(2 * kInnerLipTop) + shape.segment<2>(2 * kInnerLipBottom));
            auto at = [&](double s) { // s: -1 the left corner, 0 the middle, 1 the right corner
                const Eigen::Vector2d p = s < 0 ? middle + (-s) * (left - middle) : middle + s * (right - middle);
                return weight.at<float>(int(std::lround(p.y())), int(std::lround(p.x())));
            };
            QVERIFY2(at(0.0) > 0.95f, qPrintable(QStringLiteral("frame %1: %2 midway").arg(t).arg(at(0.0))));
            for (double s : {-0.9, 0.9})
                QVERIFY2(at(s) < 0.25f, qPrintable(QStringLiteral("frame %1: %2 near a corner").arg(t).arg(at(s))));
            ++checked;
        }
        QVERIFY(checked >= 5);
    }
};

QTEST_GUILESS_MAIN(TestHdRender)
#include "tst_hdrender.moc"
