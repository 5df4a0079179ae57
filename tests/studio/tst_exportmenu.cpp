// File ▸ Export on a studio context with the demo project (no main window): features (CSV) and
// the alignment (TextGrid) of the current sequence are written where the (test's) path prompt says
// and read back; a prompt answered with Cancel starts nothing; with a trained model in the project
// the generated video is written as H.264 + AAC, and a canceled export leaves no file; with several
// models Export asks which one and says where it wrote. (That the menu is in the window's File
// menu: tst_mainwindow.)
#include "DemoWindow.h"

#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "export/ExportMenu.h"
#include "io/FeatureCsv.h"
#include "io/MediaInfo.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;
using namespace lipsync::studio;

class TestExportMenu : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    StudioContext m_context;
    QMenu m_file;
    QWidget m_dialogParent;
    ExportMenu *m_menu = nullptr;
    QTemporaryDir m_dir;

    void waitIdle() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 120000); }
    ExportMenu *menu() const { return m_menu; }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        ErrorReporter::setBatchMode(true);
        testing::openDemo(m_context);
        m_menu = new ExportMenu(&m_context, &m_file, &m_dialogParent);
        testing::makeCurrent(m_context, 0);
        QCOMPARE(m_context.currentSequence(), 0);
        QCOMPARE(m_file.actions().size(), 1); // File ▸ Export
        QCOMPARE(menu()->menu()->actions().size(), 11 + 3); // entries and three separators
    }

    void exportsFeaturesAndAlignment()
    {
        const Sequence &s = m_context.document()->sequence(m_context.currentSequence());
        QVERIFY(s.features.rows() > 0);
        QVERIFY(!s.phones.isEmpty());
        const QString csv = m_dir.filePath("features.csv");
        const QString grid = m_dir.filePath("alignment.TextGrid");
        QString suggested;
        menu()->setPathPrompt([&](const ExportMenu::PathRequest &r) {
            suggested = r.suggestedPath;
            return r.kind == ExportMenu::Kind::Features ? csv : grid;
        });
        QSignalSpy exported(menu(), &ExportMenu::exported);
        QVERIFY(menu()->trigger(ExportMenu::Kind::Features));
        QTRY_COMPARE_WITH_TIMEOUT(exported.count(), 1, 30000);
        QVERIFY(suggested.endsWith(QString::fromStdString(s.id) + ".csv"));
        // Beside the project; the read-only demo's beside the projects Save As makes.
        const ProjectDocument *doc = m_context.document();
        QCOMPARE(QFileInfo(suggested).absolutePath(), doc->exportFolder());
        QVERIFY(doc->isReadOnly() ? doc->exportFolder().endsWith(QStringLiteral("/lipsync-projects"))
                                  : doc->exportFolder() == doc->folder());
        const FeatureTable table = readFeatureCsv(csv.toStdString());
        QCOMPARE(table.values.rows(), s.features.rows());
        QCOMPARE(table.values.cols(), s.features.cols());
        QVERIFY((table.values - s.features).cwiseAbs().maxCoeff() < 1e-6);

        QVERIFY(menu()->trigger(ExportMenu::Kind::Alignment));
        QTRY_COMPARE_WITH_TIMEOUT(exported.count(), 2, 30000);
        QCOMPARE(exported.at(1).at(0).toString(), grid);
        // The phones as in the document (a tier shorter than the words tier is padded with one
        // empty interval, which TextGrid requires).
        Tier phones = readPhoneTier(grid.toStdString());
        std::erase_if(phones.intervals, [](const Interval &i) { return i.label.empty(); });
        QCOMPARE(phones.intervals.size(), s.phones.intervals.size());
        for (size_t i = 0; i < phones.intervals.size(); ++i) {
            QCOMPARE(phones.intervals[i].label, s.phones.intervals[i].label);
            QVERIFY(std::abs(phones.intervals[i].end - s.phones.intervals[i].end) < 1e-6);
        }
    }

    // A name typed without an extension takes the chosen filter's: the format follows it.
    void typedNamesTakeTheFiltersExtension()
    {
        QCOMPARE(ExportMenu::withFilterSuffix(QStringLiteral("/x/cues"), QStringLiteral("Moho switch data (*.dat)")),
                 QStringLiteral("/x/cues.dat"));
        QCOMPARE(ExportMenu::withFilterSuffix(QStringLiteral("/x/cues.json"), QStringLiteral("Rhubarb TSV (*.tsv)")),
                 QStringLiteral("/x/cues.json"));
        QCOMPARE(ExportMenu::withFilterSuffix(QStringLiteral("/x/a.b/cues"), QStringLiteral("Praat TextGrid (*.TextGrid)")),
                 QStringLiteral("/x/a.b/cues.TextGrid"));
        QCOMPARE(ExportMenu::withFilterSuffix(QString(), QStringLiteral("MP4 video (*.mp4)")), QString());
    }

    void cancelingThePromptStartsNothing()
    {
        menu()->setPathPrompt([](const ExportMenu::PathRequest &) { return QString(); });
        QVERIFY(!menu()->trigger(ExportMenu::Kind::Features));
        QCOMPARE(m_context.taskRunner()->runningCount(), 0);
    }

    // A model trained on the demo's features, added to the project, drives the video export.
    void exportsTheGeneratedVideoAndCancels()
    {
        const Project &project = m_context.document()->project();
        std::vector<LabelledSequence> sequences;
        for (const Sequence &s : project.sequences)
            if (s.features.rows() > 0 && !s.phones.isEmpty())
                sequences.push_back({s.id, frameLabelsFromTier(s.phones, s.frameRate, int(s.features.rows())),
                                     s.features});
        auto model = createDynamicModel("hmm");
        Feedback feedback;
        model->train(sequences, feedback);
        const QString modelPath = m_dir.filePath("demo.model");
        saveModel(*model, modelPath.toStdString(), "unspecified");
        std::vector<ModelReference> models = project.models;
        models.push_back({"hmm", "HMM-mean (test)", modelPath.toStdString()});
        m_context.document()->applyModels(models);

        const QString video = m_dir.filePath("generated.mp4");
        QSignalSpy exported(menu(), &ExportMenu::exported);
        QVERIFY(menu()->exportTo(ExportMenu::Kind::Video, video));
        QTRY_COMPARE_WITH_TIMEOUT(exported.count(), 1, 120000);
        const MediaInfo info = MediaInfo::probe(video.toStdString());
        QCOMPARE(info.videoCodec, std::string("h264"));
        QCOMPARE(info.audioCodec, std::string("aac"));
        QVERIFY(std::abs(info.videoDuration - info.audioDuration) <= 1.0 / 25 + 1e-6);

        const QString canceled = m_dir.filePath("canceled.mp4");
        Task *task = menu()->exportTo(ExportMenu::Kind::SideBySide, canceled);
        QVERIFY(task);
        QTest::qWait(50);
        task->cancel();
        waitIdle();
        QCOMPARE(exported.count(), 1);
        QVERIFY(!QFile::exists(canceled));
        QVERIFY(QDir(m_dir.path()).entryList(QDir::Hidden | QDir::Files).filter(".part").isEmpty());
    }

    // With several trained models Export asks which one (cancel exports nothing), names the file
    // after it, and says where it wrote.
    void asksWhichModelAndSaysWhereItWrote()
    {
        const Project &project = m_context.document()->project();
        const ModelReference *hmm = project.model("hmm");
        QVERIFY(hmm); // trained by the test above
        std::vector<ModelReference> models = project.models;
        const QString other = m_dir.filePath("other.model");
        QVERIFY(QFile::copy(QString::fromStdString(project.resolve(hmm->file)), other));
        QFile append(other);
        QVERIFY(append.open(QIODevice::Append));
        append.write("\n"); // a different file than the HMM-mean one
        append.close();
        models.push_back({"dpds", "DPDS (test)", other.toStdString()});
        m_context.document()->applyModels(models);

        QStringList offered;
        menu()->setModelPrompt([&](const QStringList &kinds, const QStringList &) {
            offered = kinds;
            return QString();
        });
        int asked = 0;
        menu()->setPathPrompt([&](const ExportMenu::PathRequest &) {
            ++asked;
            return m_dir.filePath("never.model");
        });
        QVERIFY(!menu()->trigger(ExportMenu::Kind::Model));
        QCOMPARE(offered, QStringList({QStringLiteral("dpds"), QStringLiteral("hmm")}));
        QCOMPARE(asked, 0);

        menu()->setModelPrompt([](const QStringList &, const QStringList &) { return QStringLiteral("hmm"); });
        const QString target = m_dir.filePath("chosen.model");
        QString suggested;
        menu()->setPathPrompt([&](const ExportMenu::PathRequest &r) {
            suggested = r.suggestedPath;
            return target;
        });
        QSignalSpy exported(menu(), &ExportMenu::exported);
        QSignalSpy status(&m_context, &StudioContext::statusMessage);
        QVERIFY(menu()->trigger(ExportMenu::Kind::Model));
        QTRY_COMPARE_WITH_TIMEOUT(exported.count(), 1, 30000);
        QVERIFY2(suggested.endsWith(QStringLiteral("hmm.model")), qPrintable(suggested));
        QFile written(target), source(QString::fromStdString(project.resolve(project.model("hmm")->file)));
        QVERIFY(written.open(QIODevice::ReadOnly) && source.open(QIODevice::ReadOnly));
        QCOMPARE(written.readAll(), source.readAll());
        QVERIFY2(status.count() >= 1 && status.last().at(0).toString().contains(QDir::toNativeSeparators(target)),
                 qPrintable(status.isEmpty() ? QString() : status.last().at(0).toString()));
    }
};

QTEST_MAIN(TestExportMenu)
#include "tst_exportmenu.moc"
