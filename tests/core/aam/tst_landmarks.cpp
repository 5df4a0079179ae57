// The 23-point scheme, its iBUG-68 mapping and .pts import/export.
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "io/AtomicFile.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <set>

using namespace lipsync;

class TestLandmarks : public QObject
{
    Q_OBJECT
private slots:
    void schemeHas23NamedPointsInThreeFeatures()
    {
        const auto &defs = landmarkDefinitions();
        QCOMPARE(int(defs.size()), 23);
        std::set<std::string> names;
        for (const auto &d : defs) {
            names.insert(d.name);
            QVERIFY(d.ibugA >= 0 && d.ibugA < 68);
            QVERIFY(d.ibugB >= -1 && d.ibugB < 68);
        }
        QCOMPARE(int(names.size()), 23);
        QCOMPARE(int(landmarkIndices(LandmarkFeature::Eyes).size()), 8);
        QCOMPARE(int(landmarkIndices(LandmarkFeature::Mouth).size()), 10);
        QCOMPARE(int(landmarkIndices(LandmarkFeature::Jaw).size()), 5);
        QCOMPARE(std::string(defs[scheme23::kLeftEyeOuter].name), std::string("left_eye_outer"));
        QCOMPARE(std::string(defs[scheme23::kRightEyeOuter].name), std::string("right_eye_outer"));
        // The named points are the table's.
        using namespace scheme23;
        const std::pair<int, const char *> named[] = {
            {kLeftEyeInner, "left_eye_inner"},      {kRightEyeInner, "right_eye_inner"},
            {kMouthLeft, "mouth_left"},             {kUpperLipLeft, "upper_lip_left"},
            {kUpperLipCentre, "upper_lip_centre"},  {kUpperLipRight, "upper_lip_right"},
            {kMouthRight, "mouth_right"},           {kLowerLipRight, "lower_lip_right"},
            {kLowerLipCentre, "lower_lip_centre"},  {kLowerLipLeft, "lower_lip_left"},
            {kInnerLipTop, "inner_lip_top"},        {kInnerLipBottom, "inner_lip_bottom"},
            {kJawLeft, "jaw_left"},                 {kChin, "chin"},
            {kJawRight, "jaw_right"}};
        for (const auto &[index, name] : named)
            QCOMPARE(std::string(defs[size_t(index)].name), std::string(name));
        for (const auto &[a, b] : landmarkConnections()) {
            QVERIFY(a >= 0 && a < 23 && b >= 0 && b < 23 && a != b);
            // Connections stay within one feature.
            QVERIFY(defs[size_t(a)].feature == defs[size_t(b)].feature);
        }
    }

    void resourceFileMatchesCompiledTable()
    {
        const std::string file = readWholeFile(LIPSYNC_SOURCE_DIR "/resources/aam/landmarks23.json");
        QCOMPARE(QString::fromStdString(file), QString::fromStdString(landmarkSchemeJson()));
    }

    void mirrorPermutationIsASymmetricInvolution()
    {
        const auto &defs = landmarkDefinitions();
        for (int i = 0; i < 23; ++i) {
            const int j = mirroredLandmark(i);
            QVERIFY(j >= 0 && j < 23);
            QCOMPARE(mirroredLandmark(j), i);                     // an involution
            QVERIFY(defs[size_t(i)].feature == defs[size_t(j)].feature);
        }
        QCOMPARE(mirroredLandmark(scheme23::kLeftEyeOuter), scheme23::kRightEyeOuter);
        QCOMPARE(mirroredLandmark(scheme23::kMouthLeft), scheme23::kMouthRight);
        QCOMPARE(mirroredLandmark(20), 20); // chin
        QCOMPARE(mirroredLandmark(23), -1);
        // Connections map to connections: the mirror of the drawing is the drawing.
        std::set<std::pair<int, int>> edges;
        for (auto [a, b] : landmarkConnections())
            edges.insert({std::min(a, b), std::max(a, b)});
        for (auto [a, b] : landmarkConnections()) {
            const int ma = mirroredLandmark(a), mb = mirroredLandmark(b);
            QVERIFY(edges.count({std::min(ma, mb), std::max(ma, mb)}));
        }
    }

    void mirroringTwiceIsIdentity()
    {
        const Eigen::VectorXd t = templateShape() * 200.0 + Eigen::VectorXd::Constant(46, 150.0);
        const Eigen::VectorXd m = mirrorShape(t, 320);
        QVERIFY((m - t).cwiseAbs().maxCoeff() > 1.0);
        QVERIFY((mirrorShape(m, 320) - t).cwiseAbs().maxCoeff() < 1e-12);
        // x -> 319 - x, points renumbered: the image-left eye's outer corner comes from the right.
        QCOMPARE(m[2 * scheme23::kLeftEyeOuter], 319.0 - t[2 * scheme23::kRightEyeOuter]);
        QCOMPARE(m[2 * scheme23::kLeftEyeOuter + 1], t[2 * scheme23::kRightEyeOuter + 1]);
        QVERIFY(m[2 * scheme23::kLeftEyeOuter] < m[2 * scheme23::kRightEyeOuter]);
    }

    void symmetricTemplateIsItsOwnMirror()
    {
        // The template made symmetric about x = 0 (mirrorShape with width 1 maps x to -x).
        const Eigen::VectorXd t = templateShape();
        const Eigen::VectorXd symmetric = 0.5 * (t + mirrorShape(t, 1));
        QVERIFY((mirrorShape(symmetric, 1) - symmetric).cwiseAbs().maxCoeff() < 1e-12);
        // The template is nearly symmetric already: its midline points lie near x = 0.
        QVERIFY((symmetric - t).cwiseAbs().maxCoeff() < 0.03);
        QVERIFY(std::abs(symmetric[2 * 20]) < 1e-12);
    }

    void mapsIbug68()
    {
        Eigen::VectorXd ibug(136);
        for (int i = 0; i < 68; ++i)
            ibug.segment<2>(2 * i) << i, 1000 + 2 * i;
        const Eigen::VectorXd s = mapIbug68To23(ibug);
        QCOMPARE(s.size(), Eigen::Index(46));
        QCOMPARE(s[0], 36.0);              // outer corner: iBUG 36
        QCOMPARE(s[2], 37.5);              // upper lid: mean of 37 and 38
        QCOMPARE(s[3], 1000 + 2 * 37.5);
        QCOMPARE(s[2 * 6], 45.0);          // right outer corner
        QCOMPARE(s[2 * 20], 8.0);          // chin
        QCOMPARE(s[2 * 17], 66.0);         // inner lower lip
    }

    void templateShapeIsLevelAndNormalised()
    {
        const Eigen::VectorXd t = templateShape();
        QCOMPARE(t.size(), Eigen::Index(46));
        QVERIFY(std::abs(t[1] - t[13]) < 1e-9); // outer eye corners level
        QVERIFY(t[0] < t[12]);                  // left eye on the image left
        QVERIFY(t[41] > t[1]);                  // chin below the eyes
    }

    void parsesHeaderVariants_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("points");
        QTest::newRow("header") << "version: 1\nn_points:  3\n{\n1 2\n3 4\n5 6\n}\n" << 3;
        QTest::newRow("bare") << "1 2\n3 4\n5 6\n" << 3;
        QTest::newRow("crlf") << "version: 1\r\nn_points: 3\r\n{\r\n1 2\r\n3 4\r\n5 6\r\n}\r\n" << 3;
        QTest::newRow("blank-lines") << "\n1 2\n\n3 4\n5 6\n\n" << 3;
    }

    void parsesHeaderVariants()
    {
        QFETCH(QString, text);
        QFETCH(int, points);
        const Eigen::VectorXd p = parsePts(text.toStdString(), "t.pts");
        QCOMPARE(int(p.size() / 2), points);
        // 1-based in the file, 0-based in memory.
        QCOMPARE(p[0], 0.0);
        QCOMPARE(p[1], 1.0);
        QCOMPARE(p[5], 5.0);
    }

    void rejectsBadFiles_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("count-mismatch") << "version: 1\nn_points: 4\n{\n1 2\n3 4\n}\n" << "n_points says 4";
        QTest::newRow("not-a-number") << "1 2\n3 x\n" << "line 2";
        QTest::newRow("nan") << "1 2\nnan 4\n" << "line 2";
        QTest::newRow("unclosed") << "version: 1\nn_points: 1\n{\n1 2\n" << "missing closing";
        QTest::newRow("empty") << "version: 1\nn_points: 0\n{\n}\n" << "no points";
        QTest::newRow("one-number") << "12\n" << "expected 'x y'";
    }

    void rejectsBadFiles()
    {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        try {
            parsePts(text.toStdString(), "bad.pts");
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains(expected), e.what());
            QVERIFY2(QString::fromUtf8(e.what()).contains("bad.pts"), e.what());
        }
    }

    void roundTripsWithAndWithoutHeader()
    {
        QTemporaryDir dir;
        Eigen::VectorXd shape = templateShape() * 100.0;
        shape.array() += 150.25;
        for (bool header : {true, false}) {
            const std::string path = (dir.path() + (header ? "/h.pts" : "/n.pts")).toStdString();
            writePtsFile(path, shape, header);
            const std::string text = readWholeFile(path);
            QCOMPARE(text.starts_with("version: 1\nn_points: 23\n{\n"), header);
            const Eigen::VectorXd back = readFaceShape(path);
            QVERIFY((back - shape).cwiseAbs().maxCoeff() < 1e-5);
        }
        // LandmarkSet round trip keeps the coordinates and applies the requested state.
        const std::string path = (dir.path() + "/set.pts").toStdString();
        LandmarkSet set = landmarkSetFromShape(shape, PointState::Fixed);
        writeLandmarkSet(path, set);
        const LandmarkSet back = readLandmarkSet(path, PointState::Fixed);
        for (int i = 0; i < 23; ++i) {
            QVERIFY(std::abs(back.points[size_t(i)].x - set.points[size_t(i)].x) < 1e-5);
            QCOMPARE(back.points[size_t(i)].state, PointState::Fixed);
        }
        // A set with an unplaced point cannot be written.
        set.points[3].state = PointState::Undefined;
        QVERIFY_THROWS_EXCEPTION(Error, writeLandmarkSet(path, set));
    }

    void imports68PointFilesAs23()
    {
        QTemporaryDir dir;
        Eigen::VectorXd ibug(136);
        for (int i = 0; i < 68; ++i)
            ibug.segment<2>(2 * i) << 10 + i, 20 + 3 * i;
        const std::string path = (dir.path() + "/f68.pts").toStdString();
        writePtsFile(path, ibug, false);
        const Eigen::VectorXd s = readFaceShape(path);
        QVERIFY((s - mapIbug68To23(ibug)).cwiseAbs().maxCoeff() < 1e-5);
        writePtsFile(path, ibug.head(20), true);
        QVERIFY_THROWS_EXCEPTION(Error, readFaceShape(path)); // 10 points: neither 23 nor 68
    }

    void readsCommittedGridLabels()
    {
        const Eigen::VectorXd s = readFaceShape(LIPSYNC_TEST_DATA "/faces/grid/bbaf3s_22.pts");
        QCOMPARE(s.size(), Eigen::Index(46));
        // The GRID face is about 60 pixels between the outer eye corners at 360x288.
        const double eyes = (s.segment<2>(0) - s.segment<2>(12)).norm();
        QVERIFY2(eyes > 40 && eyes < 90, qPrintable(QString::number(eyes)));
        QVERIFY(normalisedMeanError(s, s) == 0.0);
    }
};

QTEST_GUILESS_MAIN(TestLandmarks)
#include "tst_landmarks.moc"
