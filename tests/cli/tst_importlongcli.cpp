// `lipsync project import-long` and `lipsync align` on a recording longer than three minutes (the
// ten GRID demo clips' sound seven times over, 207 s), run as a user runs them:
//  - align writes a TextGrid with every word of the 420, aligned window by window
//    (align/LongAlignment), in bounded memory;
//  - CMU Sphinx refuses it up front, naming the file and what to do instead;
//  - import-long adds one sequence per utterance, each with a WAV clip, its words and its
//    alignment, and saves the project; its --json lists them; a second run refuses the same ids.
#include "CliRun.h"

#include "io/AudioDecoder.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "io/WavWriter.h"
#include "project/Project.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;
using namespace lipsync::testing;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/");
const char *const kClips[] = {"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p",
                              "pbav2n", "pgwe6n", "pwbk1s", "sbwo1s", "srbu6n"};
constexpr int kRounds = 7;

// Writes DIR/talk.wav and DIR/talk.txt; returns the words.
std::vector<std::string> writeLongRecording(const QDir &dir)
{
    std::vector<float> samples;
    std::vector<std::string> words;
    for (int round = 0; round < kRounds; ++round)
        for (const char *clip : kClips) {
            const AudioBuffer a = AudioDecoder::decode((kDemo + clip + ".mpg").toStdString(), 16000);
            samples.insert(samples.end(), a.samples.begin(), a.samples.end());
            for (const std::string &w : readTranscript((kDemo + clip + ".align").toStdString()).words)
                words.push_back(w);
        }
    writeWav(dir.filePath(QStringLiteral("talk.wav")).toStdString(), samples, 0, samples.size(), 16000);
    Transcript t;
    t.words = words;
    writePlainTranscript(dir.filePath(QStringLiteral("talk.txt")).toStdString(), t);
    return words;
}

int spokenCount(const Tier &tier)
{
    int n = 0;
    for (const Interval &i : tier.intervals)
        n += PhoneSet::isSilence(i.label) ? 0 : 1;
    return n;
}

} // namespace

class TestImportLongCli : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_words = writeLongRecording(QDir(m_dir.path()));
        QCOMPARE(int(m_words.size()), 60 * kRounds);
    }

    void alignsInWindows()
    {
        const QString out = m_dir.filePath(QStringLiteral("talk.TextGrid"));
        const Run r = runLipsync({QStringLiteral("align"), m_dir.filePath(QStringLiteral("talk.wav")),
                                  QStringLiteral("--transcript"), m_dir.filePath(QStringLiteral("talk.txt")),
                                  QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const TextGrid grid = readTextGrid(out.toStdString());
        QVERIFY(grid.tier("words"));
        QCOMPARE(spokenCount(*grid.tier("words")), int(m_words.size()));
        const double seconds = AudioDecoder::decode(m_dir.filePath(QStringLiteral("talk.wav")).toStdString()).duration();
        QVERIFY(seconds > 180.0);
        QVERIFY2(std::abs(grid.xmax - seconds) < 0.02, qPrintable(QStringLiteral("%1 vs %2").arg(grid.xmax).arg(seconds)));
    }

    void sphinxRefusesUpFront()
    {
        const Run r = runLipsync({QStringLiteral("align"), m_dir.filePath(QStringLiteral("talk.wav")),
                                  QStringLiteral("--transcript"), m_dir.filePath(QStringLiteral("talk.txt")),
                                  QStringLiteral("--out"), m_dir.filePath(QStringLiteral("sphinx.TextGrid")),
                                  QStringLiteral("--aligner"), QStringLiteral("sphinx")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("talk.wav") && r.err.contains("CMU Sphinx aligns recordings of up to 3 min")
                     && r.err.contains("project import-long"),
                 r.err.constData());
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("sphinx.TextGrid"))));
    }

    void importsUtterances()
    {
        const QString project = m_dir.filePath(QStringLiteral("project"));
        QDir().mkpath(project + QStringLiteral("/media"));
        QVERIFY(QFile::copy(kDemo + QStringLiteral("bbaf2n.mpg"), project + QStringLiteral("/media/bbaf2n.mpg")));
        Run r = runLipsync({QStringLiteral("project"), QStringLiteral("create"), QStringLiteral("--media"),
                            project + QStringLiteral("/media"), QStringLiteral("--out"), project});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QStringList importArgs{QStringLiteral("project"), QStringLiteral("import-long"), project,
                                     m_dir.filePath(QStringLiteral("talk.wav")), QStringLiteral("--transcript"),
                                     m_dir.filePath(QStringLiteral("talk.txt")), QStringLiteral("--shortest"),
                                     QStringLiteral("1"), QStringLiteral("--json")};
        r = runLipsync(importArgs);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        const QJsonArray ids = json.value(QStringLiteral("sequences")).toArray();
        QCOMPARE(ids.size(), 10 * kRounds);
        QCOMPARE(ids.first().toString(), QStringLiteral("talk_0001"));
        QCOMPARE(json.value(QStringLiteral("words")).toInt(), int(m_words.size()));

        const Project p = Project::load(project.toStdString());
        QCOMPARE(int(p.sequences.size()), 1 + 10 * kRounds);
        int words = 0;
        for (const Sequence &s : p.sequences) {
            if (s.id == "bbaf2n")
                continue;
            QVERIFY(QFile::exists(QString::fromStdString(p.mediaPath(s))));
            QVERIFY(!s.phones.intervals.empty());
            words += spokenCount(s.words);
        }
        QCOMPARE(words, int(m_words.size()));
        // The eleventh sentence is the first clip again.
        QCOMPARE(p.sequence("talk_0011")->transcript, readTranscript((kDemo + "bbaf2n.align").toStdString()).text());

        r = runLipsync(importArgs);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("already has a sequence talk_0001"), r.err.constData());
        QCOMPARE(int(Project::load(project.toStdString()).sequences.size()), 1 + 10 * kRounds);
    }

    // From nothing: a folder that does not exist yet becomes the project; a folder with other
    // files in it and no project is refused, its files untouched.
    void importsIntoANewProject()
    {
        const QString project = m_dir.filePath(QStringLiteral("new/project"));
        Run r = runLipsync({QStringLiteral("project"), QStringLiteral("import-long"), project,
                            m_dir.filePath(QStringLiteral("talk.wav")), QStringLiteral("--transcript"),
                            m_dir.filePath(QStringLiteral("talk.txt")), QStringLiteral("--shortest"), QStringLiteral("1"),
                            QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const Project p = Project::load(project.toStdString());
        QCOMPARE(int(p.sequences.size()), 10 * kRounds);
        QCOMPARE(p.name, std::string("project"));
        // A new project says the generic aligner; a recording longer than CMU Sphinx aligns is cut
        // with the shipped model, and the command says how to align the utterances again.
        QCOMPARE(p.aligner, std::string(Project::kGenericAligner));
        QVERIFY(parseJsonObject(r.out).value("aligner").toString().endsWith("grid-s1.aligner"));
        QVERIFY2(r.err.contains("longer than CMU Sphinx aligns") && r.err.contains("lipsync align " + project.toUtf8()),
                 r.err.constData());
        const QString busy = m_dir.filePath(QStringLiteral("busy"));
        QDir().mkpath(busy);
        QFile other(busy + QStringLiteral("/notes.txt"));
        QVERIFY(other.open(QIODevice::WriteOnly));
        other.write("mine");
        other.close();
        r = runLipsync({QStringLiteral("project"), QStringLiteral("import-long"), busy,
                        m_dir.filePath(QStringLiteral("talk.wav")), QStringLiteral("--transcript"),
                        m_dir.filePath(QStringLiteral("talk.txt"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("holds files but no project"), r.err.constData());
        QCOMPARE(QDir(busy).entryList(QDir::Files), QStringList{QStringLiteral("notes.txt")});
    }

private:
    QTemporaryDir m_dir;
    std::vector<std::string> m_words;
};

QTEST_GUILESS_MAIN(TestImportLongCli)
#include "tst_importlongcli.moc"
