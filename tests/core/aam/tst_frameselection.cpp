// Choosing frames to label (aam/FrameSelection): farthest-point picks spread over the data, frames
// alike only within their own clip are left out, and the appearance descriptor of a GRID face
// ignores where the face is and how large, but not what the mouth does.
#include "aam/FaceDetector.h"
#include "aam/FrameSelection.h"
#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"

#include <QTest>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <random>
#include <set>

using namespace lipsync;

namespace {

double minimumPairDistance(const Eigen::MatrixXd &points, const std::vector<int> &picks)
{
    double best = 1e300;
    for (size_t i = 0; i < picks.size(); ++i)
        for (size_t j = i + 1; j < picks.size(); ++j)
            best = std::min(best, (points.col(picks[i]) - points.col(picks[j])).norm());
    return best;
}

} // namespace

class TestFrameSelection : public QObject
{
    Q_OBJECT
private slots:
    void picksOneFrameOfEachCluster()
    {
        // Five tight clusters of very different sizes (400, 50, 20, 5, 2 points) in 6 dimensions:
        // random picks land mostly in the big one; farthest-point picks visit every cluster.
        std::mt19937 rng(7);
        std::normal_distribution<double> noise(0.0, 0.05);
        const std::vector<int> sizes{400, 50, 20, 5, 2};
        int total = 0;
        for (int s : sizes)
            total += s;
        Eigen::MatrixXd points(6, total);
        std::vector<int> cluster;
        int column = 0;
        for (size_t c = 0; c < sizes.size(); ++c) {
            Eigen::VectorXd centre = Eigen::VectorXd::Zero(6);
            centre[Eigen::Index(c)] = 5.0;
            for (int i = 0; i < sizes[c]; ++i, ++column) {
                for (int d = 0; d < 6; ++d)
                    points(d, column) = centre[d] + noise(rng);
                cluster.push_back(int(c));
            }
        }
        const DiverseSelection s = farthestPointSample(points, 5);
        QCOMPARE(int(s.picks.size()), 5);
        std::set<int> visited;
        for (int p : s.picks)
            visited.insert(cluster[size_t(p)]);
        QCOMPARE(int(visited.size()), 5);
        // Each pick is no nearer the earlier picks than the next one is.
        for (size_t k = 2; k < s.distances.size(); ++k)
            QVERIFY(s.distances[k] <= s.distances[k - 1] + 1e-12);
        // The first pick is the one nearest the mean: in the big cluster.
        QCOMPARE(cluster[size_t(s.picks.front())], 0);
    }

    void picksSpreadFartherThanRandomSubsets()
    {
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        Eigen::MatrixXd points(2, 500);
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            points.col(j) = Eigen::Vector2d(u(rng), u(rng));
        const DiverseSelection s = farthestPointSample(points, 12);
        const double spread = minimumPairDistance(points, s.picks);
        std::vector<int> all(500);
        for (int i = 0; i < 500; ++i)
            all[size_t(i)] = i;
        double bestRandom = 0.0;
        for (int trial = 0; trial < 200; ++trial) {
            std::shuffle(all.begin(), all.end(), rng);
            bestRandom = std::max(bestRandom, minimumPairDistance(points, {all.begin(), all.begin() + 12}));
        }
        QVERIFY2(spread > bestRandom, qPrintable(QStringLiteral("%1 vs %2").arg(spread).arg(bestRandom)));
        // Twelve points in the unit square cannot all be farther apart than about 0.4; the picks'
        // spread is within a factor two of the best (Gonzalez 1985).
        QVERIFY(spread > 0.2);
    }

    void coincidentPointsGiveFewerPicks()
    {
        Eigen::MatrixXd points = Eigen::MatrixXd::Zero(3, 10);
        points.col(4) = Eigen::Vector3d(1, 0, 0);
        const DiverseSelection s = farthestPointSample(points, 5);
        QCOMPARE(int(s.picks.size()), 2);
        QVERIFY(farthestPointSample(Eigen::MatrixXd(3, 0), 5).picks.empty());
    }

    void leavesOutWhatOnlyOneClipShows()
    {
        // Ten clips share two appearances; clip 3 also holds three frames far from everything
        // (a decoding defect). Those are isolated; the shared frames, however far apart the two
        // appearances lie, are not.
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0.0, 0.1);
        Eigen::MatrixXd points(4, 0);
        std::vector<int> groups;
        auto add = [&](const Eigen::Vector4d &centre, int group) {
            points.conservativeResize(Eigen::NoChange, points.cols() + 1);
            for (int d = 0; d < 4; ++d)
                points(d, points.cols() - 1) = centre[d] + noise(rng);
            groups.push_back(group);
        };
        for (int clip = 0; clip < 10; ++clip)
            for (int i = 0; i < 6; ++i)
                add(i % 2 ? Eigen::Vector4d(0, 0, 0, 0) : Eigen::Vector4d(3, 0, 0, 0), clip);
        for (int i = 0; i < 3; ++i)
            add(Eigen::Vector4d(0, 4, 4, 0), 3);
        const std::vector<bool> isolated = isolatedColumns(points, groups);
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            QCOMPARE(bool(isolated[size_t(j)]), j >= 60);
        // One clip alone: nothing to compare with, nothing left out.
        const std::vector<bool> single = isolatedColumns(points, std::vector<int>(size_t(points.cols()), 0));
        QVERIFY(std::none_of(single.begin(), single.end(), [](bool b) { return b; }));

        std::vector<int> excluded;
        const DiverseSelection s = selectDiverseFrames(points, 4, 3, groups, &excluded);
        QCOMPARE(excluded, (std::vector<int>{60, 61, 62}));
        for (int p : s.picks)
            QVERIFY(p < 60);
    }

    void descriptorIgnoresPositionAndSizeNotTheMouth()
    {
        VideoReader video(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
        FaceDetector detector;
        QVERIFY2(detector.hasYunet(), "the YuNet model in resources/models was not found");
        if (!detector.hasDlib())
            QSKIP("dlib's shape predictor (libdlib-data) is not installed");
        auto describe = [&](const cv::Mat &frame) {
            const std::vector<FaceDetection> faces = detector.detect(frame);
            if (faces.empty())
                return Eigen::VectorXd();
            const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
            if (ibug.size() != 136)
                return Eigen::VectorXd();
            return faceAppearanceDescriptor(frame, faces.front(), mapIbug68To23(ibug));
        };
        // Frames 25-60 of the clip (speech): each one's descriptor distance to frame 20.
        const cv::Mat reference = video.frame(20);
        const Eigen::VectorXd d0 = describe(reference);
        QVERIFY(d0.size() > 0);
        QVERIFY(std::abs(d0.head(d0.size() - 30).norm() - std::sqrt(1.0 + 0.25)) < 1e-6); // unit mouth, half-weight face
        std::vector<double> speech;
        for (int t = 25; t <= 60; t += 5) {
            const Eigen::VectorXd d = describe(video.frame(t));
            QVERIFY(d.size() == d0.size());
            speech.push_back((d - d0).norm());
        }
        std::sort(speech.begin(), speech.end());
        const double median = speech[speech.size() / 2];
        // The same frame moved by (17, -9) pixels and scaled by 1.15 about its centre.
        const cv::Matx23d move(1.15, 0, 17 - 0.15 * 180, 0, 1.15, -9 - 0.15 * 144);
        cv::Mat moved;
        cv::warpAffine(reference, moved, move, reference.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
        const Eigen::VectorXd dm = describe(moved);
        QVERIFY(dm.size() == d0.size());
        const double self = (dm - d0).norm();
        QVERIFY2(self < 0.5 * median, qPrintable(QStringLiteral("moved %1, speech median %2").arg(self).arg(median)));
    }

    void descriptorWithoutPointsUsesTheKeypoints()
    {
        VideoReader video(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
        FaceDetector detector(FaceDetectorPaths::boxesOnly());
        const cv::Mat frame = video.frame(20);
        const std::vector<FaceDetection> faces = detector.detect(frame);
        QVERIFY(!faces.empty());
        const Eigen::VectorXd d = faceAppearanceDescriptor(frame, faces.front());
        QVERIFY(d.allFinite());
        QVERIFY(std::abs(d.norm() - std::sqrt(1.0 + 0.25)) < 1e-6);
        QCOMPARE(d.tail(30).cwiseAbs().maxCoeff(), 0.0); // no points, no shape part
    }
};

QTEST_GUILESS_MAIN(TestFrameSelection)
#include "tst_frameselection.moc"
