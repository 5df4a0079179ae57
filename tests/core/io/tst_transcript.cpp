// Transcripts from every accepted format, GRID .align round trip, plain text.
#include "io/GridAlign.h"
#include "io/HtkLabel.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;

class TestTranscript : public QObject
{
    Q_OBJECT
private slots:
    void allFormatsGiveTheSameWords()
    {
        QTemporaryDir dir;
        const Tier words{"words", {{0, 0.35, "sil", false}, {0.35, 0.87, "set", false}, {0.87, 0.9, "sp", false},
                                   {0.9, 1.2, "white", false}, {1.2, 3.0, "sil", false}}};
        const std::string base = dir.path().toStdString() + "/u";
        writeGridAlign(base + ".align", words);
        writeHtkLabel(base + ".lab", words);
        writeTextGrid(base + ".TextGrid", makeTextGrid({words}));
        writePlainTranscript(base + ".txt", Transcript{{"set", "white"}, {}});
        for (const std::string ext : {".align", ".lab", ".TextGrid", ".txt"}) {
            const Transcript t = readTranscript(base + ext);
            QCOMPARE(t.text(), std::string("set white"));
            QCOMPARE(t.hasTiming(), ext != ".txt");
        }
        // GRID .align round trip keeps times in 1/25000 s.
        QVERIFY(readGridAlign(base + ".align") == words);
    }

    void mfaStyleLabIsPlainText()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("m.lab");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("HE BEGAN A CONFUSED COMPLAINT\n");
        f.close();
        const Transcript t = readTranscript(path.toStdString());
        QCOMPARE(t.words.size(), size_t(5));
        QVERIFY(!t.hasTiming());
    }

    void badInput()
    {
        QTemporaryDir dir;
        const QString empty = dir.filePath("empty.txt");
        QFile f(empty);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("  \n");
        f.close();
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(empty.toStdString()));
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(dir.filePath("u.doc").toStdString()));
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(dir.filePath("missing.align").toStdString()));
    }
};

QTEST_GUILESS_MAIN(TestTranscript)
#include "tst_transcript.moc"
