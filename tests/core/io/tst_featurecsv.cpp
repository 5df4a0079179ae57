// Feature CSV files (core/io/FeatureCsv.h): values as the shortest decimals that read back exactly,
// the frame rate recorded as "# fps=RATE", files without it still read, comments, and the errors
// for a bad rate.
#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace lipsync;

class TestFeatureCsv : public QObject
{
    Q_OBJECT
private slots:
    void recordsTheFrameRate()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("clip.csv").toStdString();
        Eigen::MatrixXd values(3, 2);
        values << 1.5, -2, 0.25, 3, 1e-300, 7;
        const double ntsc = 30000.0 / 1001.0;
        writeFeatureCsv(path, values, {}, ntsc);
        const FeatureTable table = readFeatureCsv(path);
        QCOMPARE(table.frameRate, ntsc); // the shortest decimal that reads back exactly
        QCOMPARE(table.values, values);
        QCOMPARE(table.frames, (std::vector<int>{0, 1, 2}));
        QVERIFY(QByteArray::fromStdString(readWholeFile(path)).startsWith("# fps=29.97002997002997\nframe,p0,p1\n"));
        writeFeatureCsv(path, values, {4, 5, 9}, 25.0);
        QVERIFY(QByteArray::fromStdString(readWholeFile(path)).startsWith("# fps=25\nframe,p0,p1\n4,"));
        QCOMPARE(readFeatureCsv(path).frames, (std::vector<int>{4, 5, 9}));
        // No rate: nothing recorded, and the file reads as before.
        writeFeatureCsv(path, values);
        QVERIFY(QByteArray::fromStdString(readWholeFile(path)).startsWith("frame,p0,p1\n"));
        QCOMPARE(readFeatureCsv(path).frameRate, 0.0);
        QVERIFY_THROWS_EXCEPTION(Error, writeFeatureCsv(path, values, {}, -25.0));
        QVERIFY_THROWS_EXCEPTION(Error, writeFeatureCsv(path, values, {}, std::nan("")));
    }

    void valuesAreTheShortestExactDecimals()
    {
        // Every value reads back to the same double, written as the shortest decimal that does.
        Eigen::MatrixXd values(2, 3);
        values << 0.1, 1.0 / 3.0, -2.5e-300, 1e300, std::nextafter(1.0, 2.0), 0.0;
        const std::string text = formatFeatureCsv(values, {7, 8});
        QCOMPARE(QByteArray::fromStdString(text).split('\n').at(1), QByteArray("7,0.1,0.3333333333333333,-2.5e-300"));
        QCOMPARE(parseFeatureCsv(text).values, values);
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> uniform(-1e3, 1e3);
        const Eigen::MatrixXd random = Eigen::MatrixXd::NullaryExpr(40, 32, [&] { return uniform(rng); });
        const Eigen::MatrixXd back = parseFeatureCsv(formatFeatureCsv(random)).values;
        QVERIFY((back.array() == random.array()).all()); // bit for bit
    }

    void readsFilesWithoutARateAndComments()
    {
        // A file without the fps comment: no rate.
        FeatureTable old = parseFeatureCsv("frame,p0\n0,1\n1,2\n");
        QCOMPARE(old.frameRate, 0.0);
        QCOMPARE(old.values.rows(), Eigen::Index(2));
        // Without a header, comments anywhere, blank lines, spaces around the rate.
        FeatureTable t = parseFeatureCsv("\n#  fps = 50 \n# made by hand\n0,1\n# between rows\n1,2\n");
        QCOMPARE(t.frameRate, 0.0); // "fps = 50" is free text: the key is "fps=" exactly
        t = parseFeatureCsv("# made by hand\n  # fps=50\r\nframe,p0\r\n0,1\r\n1,2\r\n");
        QCOMPARE(t.frameRate, 50.0);
        QCOMPARE(t.values(1, 0), 2.0);
        // Only the first line that is not a comment may be a header.
        QVERIFY_THROWS_EXCEPTION(Error, parseFeatureCsv("0,1\nframe,p0\n"));
    }

    void rejectsABadRate_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("zero") << "# fps=0\n0,1\n";
        QTest::newRow("negative") << "# fps=-25\n0,1\n";
        QTest::newRow("not a number") << "# fps=PAL\n0,1\n";
        QTest::newRow("nan") << "# fps=nan\n0,1\n";
        QTest::newRow("inf") << "# fps=inf\n0,1\n";
        QTest::newRow("empty") << "# fps=\n0,1\n";
        QTest::newRow("twice") << "# fps=25\n# fps=25\n0,1\n";
    }
    void rejectsABadRate()
    {
        QFETCH(QString, text);
        try {
            parseFeatureCsv(text.toStdString(), "clip.csv");
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY2(QString::fromUtf8(e.what()).contains("clip.csv") && QString::fromUtf8(e.what()).contains("line"),
                     e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestFeatureCsv)
#include "tst_featurecsv.moc"
