// A new person from zero in the studio, with no file written by hand: two HD clips of a speaker the
// project never saw (tests/data/media/hd, public domain, no transcripts) become a project (File ▸
// New Project), their transcripts are proposed by speech recognition and accepted (Edit ▸ Propose
// Transcript, Accept), frames are picked and landmarked automatically (Faces ▸ Pick Frames to
// Label), an AAM is built and every clip tracked (Build AAM, Track All), the clips are aligned with
// the generic aligner the new project names (Align All), Brand is trained from other speakers'
// mouths (Models ▸ Train, Start from other speakers), faces are generated for new speech into the
// person's own video (Generate from Speech) and exported (File ▸ Export ▸ Generated Video): an MP4
// with picture and the new sound, as long as that sound. Everything is saved and reads back, the
// model recording the aligner of its phones.
#include "DemoWindow.h"

#include "align/ProjectAligner.h"
#include "align/SphinxAligner.h"
#include "annotate/FacesController.h"
#include "app/TranscriptProposer.h"
#include "build/ModelsPanel.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "dynamics/ModelFile.h"
#include "export/ExportMenu.h"
#include "io/MediaInfo.h"
#include "preview/PreviewPanel.h"
#include "render/SpeechToFace.h"
#include "tasks/Task.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

const QString kClips = QStringLiteral(LIPSYNC_SOURCE_DIR "/tests/data/media/hd/");
// New speech: a GRID clip's sound with the words a user types for it.
const QString kNewSpeech = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
const QString kNewWords = QStringLiteral("bin blue at f two now");
constexpr int kStepMs = 300000; // the longest a step may take on a slow machine

QString failure(Task *task)
{
    return task ? task->errorMessage() : QStringLiteral("not started");
}

} // namespace

class TestNewPerson : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    MainWindow *m_window = nullptr;
    QTemporaryDir m_dir;

    ProjectDocument *document() const { return m_window->context()->document(); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        if (!SphinxAligner::available())
            QSKIP("CMU Sphinx's US-English model (pocketsphinx-en-us) is not installed");
        testing::openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        m_window->context()->playback()->setAudioEnabled(false);
    }

    void cleanupTestCase() { delete m_window; }

    void fromTwoRecordingsToANewUtterance()
    {
        // File ▸ New Project from a folder of clips without transcripts.
        const QString clips = m_dir.filePath(QStringLiteral("clips"));
        QVERIFY(QDir().mkpath(clips));
        for (const char *name : {"obama_weekly_address_library.mp4", "obama_weekly_address_closeup.mp4"})
            QVERIFY(QFile::copy(kClips + QLatin1String(name), clips + QLatin1Char('/') + QLatin1String(name)));
        const QString folder = m_dir.filePath(QStringLiteral("project"));
        Task *create = m_window->files()->createFromMediaFolder(clips, folder);
        QVERIFY2(testing::waitFor(create, kStepMs), qPrintable(failure(create)));
        QTRY_COMPARE_WITH_TIMEOUT(document()->sequenceCount(), 2, 30000);
        QVERIFY(!document()->isReadOnly());
        QVERIFY(document()->project().alignsGeneric()); // a speaker the shipped aligner never heard
        for (int row = 0; row < 2; ++row)
            QVERIFY(document()->sequence(row).transcript.empty());

        // Edit ▸ Propose Transcript for each clip, then Accept: the words become checked.
        for (int row = 0; row < 2; ++row) {
            Task *propose = m_window->transcriptProposer()->propose(row);
            QVERIFY2(testing::waitFor(propose, kStepMs), qPrintable(failure(propose)));
            QVERIFY(!document()->sequence(row).transcript.empty());
            QVERIFY(document()->sequence(row).transcriptProposed);
            QVERIFY(document()->requestAcceptTranscript(row));
            QVERIFY(!document()->sequence(row).transcriptProposed);
        }

        // Faces: frames picked over both clips and landmarked automatically, the AAM built from
        // them, every clip tracked.
        m_window->context()->selectSequence(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->currentSequence() == 0, 60000);
        Task *pick = m_window->faces()->pickFramesToLabel(16, 12);
        QVERIFY2(testing::waitFor(pick, kStepMs), qPrintable(failure(pick)));
        int labelled = 0;
        for (int row = 0; row < 2; ++row)
            labelled += int(document()->sequence(row).landmarks.size());
        QVERIFY2(labelled >= 12, qPrintable(QString::number(labelled)));
        Task *build = m_window->faces()->buildAam();
        QVERIFY2(testing::waitFor(build, kStepMs), qPrintable(failure(build)));
        QVERIFY(document()->project().aam());
        Task *track = m_window->faces()->trackSequences({0, 1});
        QVERIFY2(testing::waitFor(track, kStepMs), qPrintable(failure(track)));
        for (int row = 0; row < 2; ++row) {
            const Sequence &s = document()->sequence(row);
            QCOMPARE(int(s.features.rows()), s.frameCount);
        }

        // Align All, with the aligner the project names (CMU Sphinx adapted to the speaker).
        m_window->timeline()->alignAll();
        testing::waitForTasks(m_window);
        for (int row = 0; row < 2; ++row)
            QVERIFY2(!document()->sequence(row).phones.isEmpty(), qPrintable(QString::number(row)));

        // Models ▸ Train: Brand, the studio's default model, started from other speakers' mouths
        // for the phones a few seconds of footage lack (carried onto this face by its new AAM).
        for (const QString &kind : ModelKinds::ids())
            m_window->modelsPanel()->kindCheck(kind)->setChecked(kind == QLatin1String("brand"));
        m_window->modelsPanel()->priorCheck()->setChecked(true);
        const QList<Task *> training = m_window->modelsPanel()->train();
        QCOMPARE(training.size(), 1);
        QVERIFY2(testing::waitFor(training.front(), kStepMs), qPrintable(failure(training.front())));
        QVERIFY(m_window->context()->modelStore()->dynamicModel(QStringLiteral("brand")));

        // Preview & Compare: the clip's generated face beside the recording (this prepares the
        // clip's renderer, which the new speech is drawn with).
        auto *tabs = m_window->findChild<QTabWidget *>();
        QVERIFY(tabs);
        tabs->setCurrentWidget(m_window->preview());
        QTRY_VERIFY_WITH_TIMEOUT(m_window->preview()->faces() != nullptr, 120000);
        testing::waitForTasks(m_window);

        // Generate from Speech: new words in a voice the project never had, drawn into this
        // person's own video (the current clip, re-timed to the speech).
        Task *speech = m_window->preview()->startSpeech(kNewSpeech, kNewWords, 0.0, QStringLiteral("brand"));
        QVERIFY2(testing::waitFor(speech, kStepMs), qPrintable(failure(speech)));
        const auto shown = m_window->context()->shownSpeech();
        QVERIFY(shown);
        QCOMPARE(shown->backgroundPath, m_window->context()->media()->mediaPath.toStdString());
        QVERIFY(shown->frameCount() > 60);

        // File ▸ Export ▸ Generated Video: picture and the new sound, its length.
        const QString out = m_dir.filePath(QStringLiteral("new-utterance.mp4"));
        Task *exported = m_window->exportMenu()->exportTo(ExportMenu::Kind::Video, out);
        QVERIFY2(testing::waitFor(exported, kStepMs), qPrintable(failure(exported)));
        const MediaInfo video = MediaInfo::probe(out.toStdString());
        const MediaInfo sound = MediaInfo::probe(kNewSpeech.toStdString());
        QVERIFY(video.hasVideo && video.hasAudio);
        QCOMPARE(video.width, 1280);
        QVERIFY2(std::abs(video.audioDuration - sound.audioDuration) < 0.05,
                 qPrintable(QStringLiteral("%1 vs %2").arg(video.audioDuration).arg(sound.audioDuration)));

        const QString shots = qEnvironmentVariable("LIPSYNC_TEST_SCREENSHOTS");
        if (!shots.isEmpty()) { // for looking at: the studio showing the new speech, and the video
            m_window->grab().save(shots + QStringLiteral("/new-person.png"));
            QFile::copy(out, shots + QStringLiteral("/new-person.mp4"));
        }

        // Saved, it reads back with its AAM and model.
        QVERIFY(m_window->files()->save());
        const Project saved = Project::load(folder.toStdString());
        QCOMPARE(int(saved.sequences.size()), 2);
        QVERIFY(saved.aam());
        QVERIFY(saved.model("brand"));
        // The model records whose aligner made its phones (the project's: CMU Sphinx adapted), so
        // `lipsync render` given only the model aligns new speech for this person the same way.
        const std::optional<AlignerChoice> aligner = modelTrainingAligner(saved.resolve(saved.model("brand")->file));
        QVERIFY(aligner && aligner->model == "sphinx" && aligner->adapt);
    }
};

QTEST_MAIN(TestNewPerson)
#include "tst_newperson.moc"
