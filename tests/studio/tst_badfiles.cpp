// Bad media and files in the studio, end to end: a damaged project does not open (and the open
// one stays), a truncated, empty or unsupported clip fails to load with a message naming it, a
// clip without sound loads without a waveform, damaged model files (dynamic model, AAM,
// aligner) are reported by name, and a save into a folder that cannot be written fails with a
// message while the document keeps its edits and stays modified. Every message is checked
// through ErrorReporter's log (batch mode: no box waits for a click). Damaged inputs are made
// here from repo data.
#include "../DamagedFiles.h"
#include "DemoWindow.h"

#include "annotate/FacesController.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "context/ErrorReporter.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/TaskRunner.h"
#include "timeline/TimelinePanel.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace lipsync;
using namespace lipsync::studio;
using namespace lipsync::testing;

namespace {

const QString kSource = QStringLiteral(LIPSYNC_SOURCE_DIR);
const QString kClip = kSource + QStringLiteral("/resources/demo/media/bbaf2n.mpg");

// A one-sequence project in `folder` whose clip is `media` (copied to media/<name>).
void makeProject(const QString &folder, const QString &media, const std::vector<ModelReference> &models = {})
{
    const QString name = QFileInfo(media).fileName();
    QDir().mkpath(folder + QStringLiteral("/media"));
    QFile::copy(media, folder + QStringLiteral("/media/") + name);
    Project p;
    p.name = "bad files";
    Sequence s;
    s.id = "bbaf2n";
    s.mediaFile = "media/" + name.toStdString();
    s.frameCount = 75;
    s.transcript = "bin blue at f two now";
    p.sequences.push_back(s);
    p.models = models;
    p.save(folder.toStdString());
}

// Batch mode logs instead of showing a box; lastMessage is what the box would have said. A
// marker reported first tells "nothing reported since" apart.
const QString kNothing = QStringLiteral("(nothing reported)");

void markNothingReported()
{
    ErrorReporter::report(nullptr, kNothing, QString(), QString());
}

bool reportSays(const QString &a, const QString &b = {})
{
    const QString m = ErrorReporter::lastMessage();
    return m.contains(a) && m.contains(b);
}

QByteArray said()
{
    return ErrorReporter::lastMessage().toUtf8();
}

} // namespace

class TestBadFiles : public QObject
{
    Q_OBJECT
public:
    static void initMain() { studio::testing::initStudioTest(); }

private:
    MainWindow *m_window = nullptr;
    QTemporaryDir m_dir;
    QString path(const QString &name) const { return m_dir.filePath(name); }
    ProjectDocument *doc() const { return m_window->context()->document(); }
    void idle() { QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 60000); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        lipsync::studio::testing::openDemoWindow(m_window);
        const QByteArray clip = readAll(kClip);
        QVERIFY(writeAll(path("in/empty.mpg"), {}));
        QVERIFY(writeAll(path("in/truncated.mpg"), clip.left(clip.size() / 5)));
        QVERIFY(writeAll(path("in/text.mpg"), "this is not a video\n"));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/media/no_audio_29.97fps.mp4"), path("in/silent.mp4")));
    }

    void init() { markNothingReported(); }
    void cleanupTestCase() { delete m_window; }

    void damagedProjectDoesNotOpen_data()
    {
        QTest::addColumn<QByteArray>("manifest");
        QTest::addColumn<QString>("reason");
        const QByteArray demo = readAll(kSource + QStringLiteral("/resources/demo/project.json"));
        QTest::newRow("flipped bytes") << flipped(demo) << QStringLiteral("project.json");
        QTest::newRow("truncated") << demo.left(demo.size() / 2) << QStringLiteral("not valid JSON");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("not valid JSON");
    }

    void damagedProjectDoesNotOpen()
    {
        QFETCH(QByteArray, manifest);
        QFETCH(QString, reason);
        const QString folder = path(QStringLiteral("damaged-") + QString::fromLatin1(QTest::currentDataTag()).replace(' ', '-'));
        QVERIFY(writeAll(folder + QStringLiteral("/project.json"), manifest));
        const QString before = doc()->folder();
        QVERIFY(!m_window->files()->open(folder));
        QCOMPARE(doc()->folder(), before); // the open document stays
        QVERIFY2(reportSays(QStringLiteral("could not be opened"), folder + QStringLiteral("/project.json")), said().constData());
        QVERIFY2(reportSays(reason), said().constData());
    }

    void badClipIsReportedByName_data()
    {
        QTest::addColumn<QString>("clip");
        QTest::newRow("empty") << QStringLiteral("empty.mpg");
        QTest::newRow("truncated") << QStringLiteral("truncated.mpg");
        QTest::newRow("unsupported") << QStringLiteral("text.mpg");
    }

    void badClipIsReportedByName()
    {
        QFETCH(QString, clip);
        const QString folder = path(QStringLiteral("clip-") + clip);
        makeProject(folder, path(QStringLiteral("in/") + clip));
        QVERIFY(m_window->files()->open(folder));
        idle();
        // Either the load failed and said which file, or the readable part of the clip is shown.
        if (ErrorReporter::lastMessage() == kNothing) {
            QVERIFY(m_window->context()->media());
            QVERIFY(m_window->context()->media()->frameCount() > 0);
        } else {
            QVERIFY2(reportSays(QStringLiteral("could not be read"), clip), said().constData());
        }
        QCOMPARE(doc()->sequenceCount(), 1); // the project itself is open and usable
    }

    void clipWithoutSoundLoads()
    {
        const QString folder = path(QStringLiteral("silent"));
        makeProject(folder, path(QStringLiteral("in/silent.mp4")));
        QVERIFY(m_window->files()->open(folder));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() != nullptr, 30000);
        idle();
        QVERIFY(m_window->context()->media()->frameCount() > 0);
        QVERIFY(!m_window->context()->media()->peaks);
        QVERIFY(!m_window->context()->media()->audioError.isEmpty());
        QCOMPARE(ErrorReporter::lastMessage(), kNothing);
    }

    void damagedModelsAreReportedByName()
    {
        const QString folder = path(QStringLiteral("models"));
        QVERIFY(writeAll(folder + QStringLiteral("/models/hmm.model"), flipped(QByteArray(4000, '{'))));
        const QByteArray aam = readAll(kSource + QStringLiteral("/resources/demo/aam/demo.aam"));
        QVERIFY(writeAll(folder + QStringLiteral("/aam/flipped.aam"), flipped(aam)));
        makeProject(folder, kClip, {{"hmm", "damaged hmm", "models/hmm.model"}, {"aam", "damaged aam", "aam/flipped.aam"}});
        QVERIFY(m_window->files()->open(folder));
        idle();
        // The dynamic model is read on open.
        QVERIFY2(reportSays(QStringLiteral("could not be loaded"), QStringLiteral("hmm.model")), said().constData());
        // The AAM when tracking needs it.
        markNothingReported();
        m_window->faces()->trackSequenceAction()->trigger();
        idle();
        QVERIFY2(reportSays(QStringLiteral("AAM could not be loaded"), QStringLiteral("flipped.aam")), said().constData());
        QVERIFY(!doc()->isModified());
    }

    void damagedAlignerIsReportedByName()
    {
        const QString folder = path(QStringLiteral("aligner"));
        makeProject(folder, kClip);
        const QByteArray aligner = readAll(kSource + QStringLiteral("/resources/aligner/grid-s1.aligner"));
        const QString damaged = path(QStringLiteral("in/damaged.aligner"));
        QVERIFY(writeAll(damaged, aligner.left(aligner.size() / 3)));
        QVERIFY(m_window->files()->open(folder));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() != nullptr, 30000);
        idle();
        qputenv("LIPSYNC_ALIGNER_MODEL", damaged.toUtf8());
        auto *timeline = m_window->findChild<TimelinePanel *>();
        QVERIFY(timeline);
        timeline->alignSequence();
        idle();
        qunsetenv("LIPSYNC_ALIGNER_MODEL");
        QVERIFY2(reportSays(QStringLiteral("alignment failed"), QStringLiteral("damaged.aligner")), said().constData());
        QVERIFY(!doc()->isModified()); // nothing applied
    }

    void saveIntoAnUnwritableFolderKeepsTheEdits()
    {
        const QString folder = path(QStringLiteral("unwritable"));
        makeProject(folder, kClip);
        QVERIFY(m_window->files()->open(folder));
        idle();
        const QByteArray saved = readAll(folder + QStringLiteral("/project.json"));
        QVERIFY(doc()->requestTranscriptChange(0, QStringLiteral("an edit to keep")));
        const QString manifest = folder + QStringLiteral("/project.json");
        const bool root = ::geteuid() == 0;
        if (root) {
            // Root ignores permission bits: make the manifest's path a folder, which no one
            // can replace with a file.
            QVERIFY(QFile::remove(manifest));
            QVERIFY(QDir().mkpath(manifest + QStringLiteral("/in-the-way")));
        } else {
            QVERIFY(QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner));
        }
        const bool savedOk = m_window->files()->save();
        if (!root)
            QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QVERIFY(!savedOk);
        QVERIFY2(reportSays(QStringLiteral("could not be saved"), manifest), said().constData());
        QVERIFY(doc()->isModified());
        QCOMPARE(doc()->sequence(0).transcript, std::string("an edit to keep"));
        if (!root)
            QCOMPARE(readAll(manifest), saved); // the old file is intact
        // Save As elsewhere still works: nothing was lost.
        const QString elsewhere = path(QStringLiteral("elsewhere"));
        const bool movedOk = [&] {
            try {
                doc()->saveTo(elsewhere);
                return true;
            } catch (const std::exception &) {
                return false;
            }
        }();
        QVERIFY(movedOk);
        QVERIFY(readAll(elsewhere + QStringLiteral("/project.json")).contains("an edit to keep"));
        QVERIFY(!doc()->isModified());
    }
};

QTEST_MAIN(TestBadFiles)
#include "tst_badfiles.moc"
