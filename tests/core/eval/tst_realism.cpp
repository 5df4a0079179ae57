// The realism report (docs/models.md §6.5): each measure on signals and images with known answers,
// and one run on the bundled demo project, where the tracked parameters' re-synthesis must follow
// the recorded lips.
#include "../../SanitizedBuild.h"
#include "eval/RealismMetrics.h"
#include "eval/RealismReport.h"
#include "io/AudioDecoder.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <Eigen/Geometry>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QTest>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace lipsync;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> wave(int frames, double amplitude = 1.0, double offset = 0.0)
{
    std::vector<double> out;
    for (int t = 0; t < frames; ++t)
        out.push_back(offset + amplitude * (std::sin(0.37 * t) + 0.5 * std::sin(0.11 * t + 1.0)));
    return out;
}

// 68 iBUG points: eyes' outer corners (36, 45) `eyeDistance` apart on a level line, inner lips
// (61-63 above, 65-67 below) `opening` apart, then rotated by `angle` and shifted.
Eigen::VectorXd face(double eyeDistance, double opening, double angle, Eigen::Vector2d shift)
{
    Eigen::VectorXd p = Eigen::VectorXd::Zero(136);
    auto set = [&](int i, double x, double y) {
        p[2 * i] = x;
        p[2 * i + 1] = y;
    };
    set(36, -eyeDistance / 2, 0);
    set(45, eyeDistance / 2, 0);
    for (int i = 48; i < 60; ++i)
        set(i, 0.3 * eyeDistance * std::cos(i), eyeDistance + 0.2 * eyeDistance * std::sin(i));
    set(60, -0.2 * eyeDistance, eyeDistance);
    set(64, 0.2 * eyeDistance, eyeDistance);
    for (int k = 0; k < 3; ++k) {
        const double x = (k - 1) * 0.1 * eyeDistance;
        set(61 + k, x, eyeDistance - opening / 2);
        set(67 - k, x, eyeDistance + opening / 2);
    }
    const Eigen::Rotation2Dd r(angle);
    for (int i = 0; i < 68; ++i) {
        const Eigen::Vector2d q = r * Eigen::Vector2d(p[2 * i], p[2 * i + 1]) + shift;
        set(i, q.x(), q.y());
    }
    return p;
}

} // namespace

class TestRealism : public QObject
{
    Q_OBJECT
private slots:
    void openingIsScaleAndRollFree()
    {
        QVERIFY(std::abs(innerLipOpening(face(100, 10, 0, {0, 0})) - 0.1) < 1e-12);
        QVERIFY(std::abs(innerLipOpening(face(230, 23, 0.4, {50, 70})) - 0.1) < 1e-12);
        QCOMPARE(innerLipOpening(face(100, 0, 0.2, {3, 4})), 0.0);
        QVERIFY(std::isnan(innerLipOpening(Eigen::VectorXd::Zero(46))));
        const cv::Rect2d box = mouthBox(face(100, 10, 0, {0, 0}), 0.0);
        QVERIFY(box.width > 0 && box.height > 0);
        QVERIFY(mouthBox(face(100, 10, 0, {0, 0}), 0.25).area() > box.area());
    }

    void correlationOfIdenticalOpenings()
    {
        const std::vector<double> a = wave(75);
        QVERIFY(std::abs(pearsonOverFrames(a, a) - 1.0) < 1e-12);
        std::vector<double> negated;
        for (double v : a)
            negated.push_back(3.0 - 2.0 * v);
        QVERIFY(std::abs(pearsonOverFrames(negated, a) + 1.0) < 1e-12);
        // Frames without a face on either side are left out, not counted as zeros.
        std::vector<double> gaps = a;
        gaps[3] = gaps[40] = kNaN;
        std::vector<double> other = a;
        other[10] = kNaN;
        QVERIFY(std::abs(pearsonOverFrames(gaps, other) - 1.0) < 1e-12);
        QVERIFY(std::isnan(pearsonOverFrames(std::vector<double>(75, 1.0), a)));
    }

    void articulationOfHalfAmplitude()
    {
        const std::vector<double> recorded = wave(75, 1.0, 0.3), generated = wave(75, 0.5, 0.1);
        QVERIFY(std::abs(articulationRatio(generated, recorded) - 0.5) < 1e-12);
        QVERIFY(std::abs(articulationRatio(recorded, recorded) - 1.0) < 1e-12);
        QVERIFY(std::isnan(articulationRatio(recorded, std::vector<double>(75, 0.2))));
    }

    void lagOfAShiftedSignalIsRecovered()
    {
        std::mt19937 rng(7);
        std::normal_distribution<double> noise;
        std::vector<double> energy;
        for (int t = 0; t < 120; ++t)
            energy.push_back(noise(rng));
        for (int shift : {-4, -1, 0, 2, 5}) {
            // opening[t + shift] = energy[t]: the lips follow the sound by `shift` frames.
            std::vector<double> opening(energy.size(), kNaN);
            for (int t = 0; t < int(energy.size()); ++t)
                if (t + shift >= 0 && t + shift < int(energy.size()))
                    opening[size_t(t + shift)] = energy[size_t(t)];
            QCOMPARE(avLag(opening, energy, 5), double(shift));
        }
        QVERIFY(std::isnan(avLag(std::vector<double>(50, kNaN), energy, 5)));
    }

    void audioEnergyPerVideoFrame()
    {
        AudioBuffer audio;
        audio.sampleRate = 1000;
        audio.samples.assign(1000, 0.1f); // 25 frames at 25 fps, 40 samples each, power 0.01
        for (size_t i = 400; i < 440; ++i)
            audio.samples[i] = 1.0f;      // frame 10: power 1
        const std::vector<double> e = audioEnergyPerFrame(audio, FrameClock::uniform(25.0, 26));
        QCOMPARE(e.size(), size_t(26));
        QVERIFY(std::abs(e[0] + 20.0) < 1e-4);
        QVERIFY(std::abs(e[10]) < 1e-4);
        QVERIFY(std::isnan(e[25])); // past the end of the sound
    }

    void closuresOnAConstructedTier()
    {
        std::vector<double> level;
        for (int i = 0; i <= 100; ++i)
            level.push_back(i);
        // 10th percentile 10, 90th 90: closed at 10 + 0.4 * 80 by default.
        QVERIFY(std::abs(closedLevel(level) - 42.0) < 1e-12);
        QVERIFY(std::abs(closedLevel(level, 0.1) - 18.0) < 1e-12);

        Tier phones{"phones",
                    {{0.00, 0.20, "sil", false},
                     {0.20, 0.28, "B", false},  // frames 5, 6
                     {0.28, 0.40, "IH", false}, // 7..9
                     {0.40, 0.48, "M", false},  // 10, 11
                     {0.48, 0.60, "AA", false},
                     {0.60, 0.64, "P", false},  // 15
                     {0.64, 1.00, "sil", false},
                     {1.00, 1.10, "M", false}}}; // past the 25 frames
        const std::vector<FrameRange> segments = bilabialSegments(phones, FrameClock::uniform(25.0, 25), 0);
        QCOMPARE(segments.size(), size_t(3));
        QCOMPARE(segments[0].first, 5);
        QCOMPARE(segments[0].last, 6);
        QCOMPARE(segments[1].first, 10);
        QCOMPARE(segments[1].last, 11);
        QCOMPARE(segments[2].first, 15);
        QCOMPARE(segments[2].last, 15);

        std::vector<double> opening(25, 0.3);
        opening[6] = 0.01;  // the B closes
        opening[11] = kNaN; // the M has no face in its second frame and stays open in its first
        opening[15] = 0.05; // the P closes at the level itself
        QCOMPARE(closedSegments(opening, segments, 0.05), 2);
        QCOMPARE(closedSegments(opening, segments, 0.009), 0);
        QCOMPARE(closedSegments(opening, segments, 0.3), 3);
        // Widened by a frame either way for the aligner's error: the IH's first frame counts for the B.
        const std::vector<FrameRange> widened = bilabialSegments(phones, FrameClock::uniform(25.0, 25));
        QCOMPARE(widened[0].first, 4);
        QCOMPARE(widened[0].last, 7);
        QCOMPARE(widened[2].last, 16);
        opening[6] = 0.3;
        opening[7] = 0.02;
        QCOMPARE(closedSegments(opening, segments, 0.05), 1);
        QCOMPARE(closedSegments(opening, widened, 0.05), 2);
    }

    // The default closed level is the one that agrees best with eye labels of recorded frames
    // (docs/closure-labels.tsv): on a clip whose 10th-90th percentile spread runs from 0 to 1, a
    // frame of relative opening r reads closed when r <= the level.
    void closedLevelAgreesWithTheEye()
    {
        QFile file(LIPSYNC_SOURCE_DIR "/docs/closure-labels.tsv");
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        std::vector<std::pair<double, bool>> labels; // r, closed by eye
        for (const QByteArray &line : file.readAll().split('\n')) {
            const QList<QByteArray> f = line.split('\t');
            if (line.startsWith('#') || f.size() != 4 || f[0] == "clip")
                continue;
            QVERIFY(f[3] == "closed" || f[3] == "open");
            labels.emplace_back(f[2].toDouble(), f[3] == "closed");
        }
        QCOMPARE(labels.size(), size_t(59));
        std::vector<double> unitSpread;
        for (int i = 0; i <= 100; ++i)
            unitSpread.push_back((i - 10) / 80.0); // 10th percentile 0, 90th 1
        const auto agreeing = [&](double level) {
            return std::count_if(labels.begin(), labels.end(),
                                 [&](const auto &l) { return (l.first <= level) == l.second; });
        };
        const double level = closedLevel(unitSpread);
        QCOMPARE(agreeing(level), 49L);
        for (int percent = 10; percent <= 70; percent += 5)
            QVERIFY2(agreeing(percent / 100.0) <= agreeing(level), qPrintable(QString::number(percent)));
        QCOMPARE(agreeing(0.3), 42L); // 30 % of the spread
    }

    void sharpness()
    {
        cv::Mat flat(60, 80, CV_8UC3, cv::Scalar(90, 120, 150));
        QCOMPARE(gradientEnergy(flat, cv::Rect2d(10, 10, 40, 30)), 0.0);
        cv::Mat edges = flat.clone();
        for (int y = 0; y < edges.rows; ++y)
            for (int x = 0; x < edges.cols; ++x)
                if ((x / 4 + y / 4) % 2)
                    edges.at<cv::Vec3b>(y, x) = cv::Vec3b(20, 30, 40);
        cv::Mat blurred;
        cv::GaussianBlur(edges, blurred, cv::Size(7, 7), 2.0);
        const double sharp = gradientEnergy(edges, cv::Rect2d(10, 10, 40, 30));
        QVERIFY(sharp > 0);
        QVERIFY(gradientEnergy(blurred, cv::Rect2d(10, 10, 40, 30)) < 0.5 * sharp);
        QVERIFY(std::isnan(gradientEnergy(flat, cv::Rect2d(100, 100, 10, 10))));
    }

    void seamColourDifference()
    {
        // A disc composited with a feathered edge.
        const cv::Size size(120, 100);
        cv::Mat weight(size, CV_8U, cv::Scalar(0));
        cv::circle(weight, {60, 50}, 30, cv::Scalar(255), cv::FILLED);
        cv::GaussianBlur(weight, weight, cv::Size(5, 5), 1.0);
        auto composite = [&](const cv::Mat &background, cv::Scalar colour) {
            cv::Mat out = background.clone();
            for (int y = 0; y < size.height; ++y)
                for (int x = 0; x < size.width; ++x) {
                    const double a = weight.at<uchar>(y, x) / 255.0;
                    for (int c = 0; c < 3; ++c)
                        out.at<cv::Vec3b>(y, x)[c] = cv::saturate_cast<uchar>(
                            a * colour[c] + (1 - a) * background.at<cv::Vec3b>(y, x)[c]);
                }
            return out;
        };
        const cv::Scalar skin(110, 140, 190);
        const cv::Mat &measured = weight;

        const cv::Mat recording(size, CV_8UC3, skin);
        // The same colour as around it: no seam, in the render or the recording.
        const SeamDeltaE same = seamDeltaE(composite(recording, skin), recording, measured);
        QVERIFY(same.pairs > 50);
        QVERIFY(same.frame < 1e-3);
        QVERIFY(same.reference < 1e-3);
        // A visibly different colour: the ΔE of the two colours (measured by OpenCV's Lab).
        const cv::Scalar pale(160, 170, 200);
        const SeamDeltaE step = seamDeltaE(composite(recording, pale), recording, measured);
        cv::Mat two(1, 2, CV_32FC3), lab;
        two.at<cv::Vec3f>(0, 0) = cv::Vec3f(float(skin[0]), float(skin[1]), float(skin[2])) / 255.0f;
        two.at<cv::Vec3f>(0, 1) = cv::Vec3f(float(pale[0]), float(pale[1]), float(pale[2])) / 255.0f;
        cv::cvtColor(two, lab, cv::COLOR_BGR2Lab);
        const double expected = cv::norm(lab.at<cv::Vec3f>(0, 0) - lab.at<cv::Vec3f>(0, 1));
        QVERIFY2(std::abs(step.frame - expected) < 0.05 * expected,
                 qPrintable(QStringLiteral("%1 vs %2").arg(step.frame).arg(expected)));
        QVERIFY(step.reference < 1e-3);
        // No region: nothing to pair.
        QVERIFY(std::isnan(seamDeltaE(recording, recording, cv::Mat(size, CV_8U, cv::Scalar(0))).frame));
    }

    void naturalSeamOfDrawnInsides()
    {
        const double nan = std::nan("");
        // Frames 0-1 drew closed lips (the same pixels of the recording stand), 2-3 drew insides
        // opened to 10 and 31 px; the recording's own inner-lip edge in its open frames 4-10.
        const std::vector<double> samePixels{7, 8, 3, 4, 9, 9, 9, 9, 9, 9, 9};
        const std::vector<double> asked{nan, nan, 10, 31, nan, nan, nan, nan, nan, nan, nan};
        const std::vector<double> opening{20, 22, 2, 3, 4, 9, 10, 11, 12, 30, 40};
        const std::vector<double> ownEdge{nan, nan, nan, nan, 1, 10, 20, 30, 40, 50, 60};
        const std::vector<double> natural = naturalSeamDeltaE(samePixels, asked, opening, ownEdge);
        QCOMPARE(natural.size(), samePixels.size());
        QCOMPARE(natural[0], 7.0);
        QCOMPARE(natural[1], 8.0);
        // 10 px: the five frames opened most nearly as wide (9, 10, 11, 12 and 4 px).
        QCOMPARE(natural[2], (10.0 + 20 + 30 + 40 + 1) / 5);
        // 31 px: 30, 40, 22 px have no own edge; 12, 11 and 10 px follow.
        QCOMPARE(natural[3], (50.0 + 60 + 40 + 30 + 20) / 5);
        QCOMPARE(natural[4], 9.0);
        // No open recorded frame: no real edge to compare a drawn inside with.
        const std::vector<double> none(ownEdge.size(), nan);
        const std::vector<double> undefined = naturalSeamDeltaE(samePixels, asked, opening, none);
        QVERIFY(std::isnan(undefined[2]) && std::isnan(undefined[3]));
        QCOMPARE(undefined[0], 7.0);
    }

    // One small run on the bundled demo: 2 folds, the HMM-mean model besides the tracked
    // re-synthesis, and driven live (phones recognised from the sound). The tracked parameters
    // re-synthesised by the AAM must follow the recorded lips closely; generation from phones
    // alone follows them less, and from recognised phones it still follows them. Sanitizer builds render
    // and run dlib many times slower (over 300 s for the ten clips): they check memory on two.
    // The observer's judgements split by what was drawn: rendered frames that differ from the
    // recording only where closed lips were drawn are called rendered, those moved like the
    // recording are called rendered about as often as the recording itself, and a kind never
    // drawn has no figure; a clip whose drawing does not match its frames is left out of the split.
    void observerSplitsByDrawing()
    {
        std::mt19937 random(2007);
        std::normal_distribution<float> normal;
        auto rows = [&](int n, float shift) {
            Eigen::MatrixXf m(n, 6);
            for (Eigen::Index i = 0; i < m.size(); ++i)
                m.data()[i] = normal(random);
            m.col(2).array() += shift;
            return m;
        };
        std::vector<ObservedClip> clips;
        for (int c = 0; c < 12; ++c) {
            ObservedClip clip;
            clip.fold = c % 4;
            clip.real = rows(40, 0.0f);
            clip.rendered = rows(40, 0.0f);
            clip.drawing.assign(40, FrameDrawing::Warped);
            for (int i = 0; i < 10; ++i) { // a quarter of the frames: closed lips, plain to see
                clip.rendered(i, 2) += 4.0f;
                clip.drawing[size_t(i)] = FrameDrawing::Closed;
            }
            clips.push_back(clip);
        }
        clips.back().drawing.pop_back(); // not matching its frames: not split
        const std::vector<ObserverAccuracy> folds = observeByFold(clips, 4);
        QCOMPARE(folds.size(), size_t(4));
        double warpedSum = 0, recordedSum = 0;
        for (const ObserverAccuracy &a : folds) {
            const double closed = a.drawnJudgedRendered[size_t(FrameDrawing::Closed)];
            const double warped = a.drawnJudgedRendered[size_t(FrameDrawing::Warped)];
            qInfo("called rendered: recorded %.2f, warped %.2f, closed lips %.2f", a.recordedJudgedRendered, warped,
                  closed);
            QVERIFY2(closed > 0.9, qPrintable(QString::number(closed)));
            warpedSum += warped;
            recordedSum += a.recordedJudgedRendered;
            QVERIFY(!std::isfinite(a.drawnJudgedRendered[size_t(FrameDrawing::Inside)]));
            QVERIFY(!std::isfinite(a.drawnJudgedRendered[size_t(FrameDrawing::Narrowed)]));
            // Accuracy is the two sides' shares averaged (as many recorded as rendered frames).
            const double hits = (closed * 30 + warped * 90) / 120; // the fold's 3 clips: 30 closed, 90 warped
            if (&a != &folds.back())
                QVERIFY(std::abs(a.frames - 0.5 * (1.0 - a.recordedJudgedRendered + hits)) < 1e-9);
        }
        // Over the folds, the moved frames are called rendered about as often as the recording's.
        QVERIFY2(std::abs(warpedSum - recordedSum) / 4 < 0.1, qPrintable(QString::number((warpedSum - recordedSum) / 4)));
    }

    void demoProject()
    {
        if (!QFileInfo::exists(QStringLiteral("/usr/share/dlib/shape_predictor_68_face_landmarks.dat")))
            QSKIP("dlib's 68-point predictor (libdlib-data) is not installed");
        Project project = Project::load(LIPSYNC_SOURCE_DIR "/resources/demo");
#ifdef LIPSYNC_SANITIZED_BUILD
        project.sequences.resize(2);
#else
        project.sequences.resize(6); // three a fold: the controls pair sequences within a fold
#endif
        const int n = int(project.sequences.size());
        RealismOptions options;
        options.crossValidation.folds = 2;
        options.crossValidation.kinds = {"hmm"};
#ifndef LIPSYNC_SANITIZED_BUILD // the live path's memory is checked by tst_livesession there
        options.liveAcousticModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";
        options.liveBigram = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.bigram";
#endif
        const bool live = !options.liveAcousticModel.empty();
        Feedback feedback;
        const RealismResult r = evaluateRealism(project, options, feedback);
        QCOMPARE(r.sequences, n);
        QCOMPARE(r.methods.size(), size_t(live ? 4 : 3));
        QCOMPARE(r.methods.back().kind, std::string("re-encoded recording"));
        QCOMPARE(r.methods[0].kind, std::string("tracked"));
        if (live) {
            QCOMPARE(r.methods[2].kind, std::string("live hmm"));
            QVERIFY2(r.methods[2].metrics.at("correlation").mean > 0.3,
                     qPrintable(QString::number(r.methods[2].metrics.at("correlation").mean)));
        }
        QCOMPARE(r.perSequence.size(), size_t(n));
        QVERIFY(r.frames >= 70 * n);
        QVERIFY(r.skippedFrames < r.frames / 10);
        const auto &tracked = r.methods[0].metrics;
        const auto &hmm = r.methods[1].metrics;
        qInfo("tracked: correlation %.3f, articulation %.3f, closure %.3f, lag %.3f, sharpness %.3f, seam %.2f "
              "(recording %.2f); hmm: correlation %.3f, articulation %.3f",
              tracked.at("correlation").mean, tracked.at("articulation").mean, tracked.at("closure").mean,
              tracked.at("lag").mean, tracked.at("sharpness").mean, tracked.at("seamDeltaE").mean,
              tracked.at("seamDeltaERecorded").mean, hmm.at("correlation").mean, hmm.at("articulation").mean);
        QVERIFY(tracked.at("correlation").mean > 0.8);
        QVERIFY(tracked.at("articulation").mean > 0.5 && tracked.at("articulation").mean < 1.5);
        QVERIFY(hmm.at("correlation").mean < tracked.at("correlation").mean);
        QVERIFY(std::abs(tracked.at("lag").mean) <= 1.0);
        QVERIFY(tracked.at("sharpness").mean > 0);
        // The tracked parameters render the recording itself (its own face, moved nowhere): nothing
        // is synthesised, so there is no seam to measure.
        QVERIFY(!std::isfinite(tracked.at("seamDeltaE").mean));
        QVERIFY(!std::isfinite(tracked.at("seamDeltaENatural").mean));
        // A model's mouth is drawn where it differs: its seam, and the real edge it is judged by.
        qInfo("hmm: seam %.2f, recording at the same pixels %.2f, a real edge there %.2f",
              hmm.at("seamDeltaE").mean, hmm.at("seamDeltaERecorded").mean, hmm.at("seamDeltaENatural").mean);
        QVERIFY(std::isfinite(hmm.at("seamDeltaE").mean) && std::isfinite(hmm.at("seamDeltaENatural").mean));
        // The new measures: the tracked render is the recording itself, so in speech too it
        // correlates fully, closes every /p b m/ the recording closes, and no observer can tell it
        // from the recording (nor the recording from its own re-encode); another sequence's render
        // correlates far less than the model's own; the observer's accuracy is a fraction.
        QVERIFY(tracked.at("speechCorrelation").mean > 0.99);
        QVERIFY(std::abs(tracked.at("closureRecall").mean - 1.0) < 1e-9);
        QVERIFY2(std::abs(tracked.at("observerFrames").mean - 0.5) < 0.1,
                 qPrintable(QString::number(tracked.at("observerFrames").mean)));
        const auto &reencoded = r.methods.back().metrics;
        // Encoded losslessly at full colour resolution (the default), a second encode of the
        // recording gives nothing away.
        QVERIFY2(std::abs(reencoded.at("observerFrames").mean - 0.5) < 0.05,
                 qPrintable(QString::number(reencoded.at("observerFrames").mean)));
        QVERIFY(!std::isfinite(reencoded.at("correlation").mean));
        if (n >= 4) // the control pairs sequences within a fold
            QVERIFY2(hmm.at("controlCorrelation").mean < hmm.at("correlation").mean,
                     qPrintable(QString("%1 vs %2").arg(hmm.at("controlCorrelation").mean).arg(hmm.at("correlation").mean)));
        QVERIFY(hmm.at("observerFrames").mean >= 0.0 && hmm.at("observerFrames").mean <= 1.0);
        // Its judgements split by what the renderer drew: a model's frames are moved at least; the
        // re-encoded recording has nothing drawn to split by.
        for (const char *share : {"observerRecorded", "observerWarped"})
            QVERIFY2(hmm.at(share).mean >= 0.0 && hmm.at(share).mean <= 1.0, share);
        QVERIFY(std::isfinite(reencoded.at("observerRecorded").mean));
        QVERIFY(!std::isfinite(reencoded.at("observerWarped").mean));
        QVERIFY(hmm.count("observerNarrowed") && !std::isfinite(reencoded.at("observerNarrowed").mean));
        const double narrowed = hmm.at("observerNarrowed").mean;
        QVERIFY2(!std::isfinite(narrowed) || (narrowed >= 0.0 && narrowed <= 1.0), qPrintable(QString::number(narrowed)));
        QVERIFY(std::isfinite(hmm.at("falseClosuresRecorded").mean));
        qInfo("hmm: speech correlation %.3f (control %.3f), closure recall %.2f, false closures %.2f/s "
              "(recorded %.2f/s), observer %.2f per frame, %.2f per video; re-encode %.2f",
              hmm.at("speechCorrelation").mean, hmm.at("controlSpeechCorrelation").mean, hmm.at("closureRecall").mean,
              hmm.at("falseClosures").mean, hmm.at("falseClosuresRecorded").mean, hmm.at("observerFrames").mean,
              hmm.at("observerVideos").mean, reencoded.at("observerFrames").mean);
        // The mouth the parameters give (what the animation exports carry) is the mouth the render
        // shows: tracked and generated alike.
        qInfo("shape correlation: tracked %.3f, hmm %.3f", tracked.at("shapeCorrelation").mean,
              hmm.at("shapeCorrelation").mean);
        QVERIFY(tracked.at("shapeCorrelation").mean > 0.8);
        QVERIFY(hmm.at("shapeCorrelation").mean > 0.6);
        QVERIFY(!std::isfinite(reencoded.at("shapeCorrelation").mean));
        // Drawn into the footage half the clip away, the tracked parameters still show the
        // recording's mouth (the warp moves the other frame's lips to them), but less faithfully
        // than into their own frame, where nothing moves at all; and a model's render there keeps
        // none of the recording's movement, so it reads lower than in its own frames, though above
        // another clip's render.
        qInfo("speech correlation in other footage: tracked %.3f, hmm %.3f", tracked.at("shiftedSpeechCorrelation").mean,
              hmm.at("shiftedSpeechCorrelation").mean);
        QVERIFY(tracked.at("shiftedSpeechCorrelation").mean > 0.5);
        QVERIFY(tracked.at("shiftedSpeechCorrelation").mean < tracked.at("speechCorrelation").mean);
        QVERIFY(hmm.at("shiftedSpeechCorrelation").mean < hmm.at("speechCorrelation").mean);
        if (n >= 4) // the control pairs sequences within a fold
            QVERIFY(hmm.at("shiftedSpeechCorrelation").mean > hmm.at("controlSpeechCorrelation").mean);
        QVERIFY(!std::isfinite(reencoded.at("shiftedSpeechCorrelation").mean));
        const QJsonObject json = r.toJson();
        QVERIFY(json.contains(QStringLiteral("methods")));
        QCOMPARE(json[QStringLiteral("perSequence")].toArray().size(), n);
    }

    void refusesAProjectWithoutAnAam()
    {
        Project project;
        Feedback feedback;
        QVERIFY_THROWS_EXCEPTION(Error, evaluateRealism(project, RealismOptions{}, feedback));
    }
};

QTEST_GUILESS_MAIN(TestRealism)
#include "tst_realism.moc"
