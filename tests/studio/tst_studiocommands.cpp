// The studio's commands on a context without a window (Aegisub's cmd::Command): each is enabled
// exactly when it validates on the context, re-read as the sequence and frame change; running one
// that does not validate does nothing; the sequence commands load the sequence through the context
// (its media decoded in the background, the first frame shown), and a newer request supersedes a
// pending one; a panel's own actions validate as commands; a command goes with the object it
// belongs to.
#include "DemoWindow.h"

#include "context/CommandRegistry.h"
#include "context/StudioActions.h"
#include "context/StudioContext.h"
#include "context/PlaybackController.h"
#include "document/ProjectDocument.h"
#include "timeline/TimelinePanel.h"
#include "util/Error.h"

#include <QAction>
#include <QSignalSpy>
#include <QTest>
#include <QWidget>

#include <memory>

using namespace lipsync;
using namespace lipsync::studio;

class TestStudioCommands : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    StudioContext m_context;
    QWidget m_owner;
    std::unique_ptr<StudioActions> m_actions;

private slots:
    void initTestCase()
    {
        ErrorReporter::setBatchMode(true);
        m_actions = std::make_unique<StudioActions>(&m_owner, &m_context);
    }

    void nothingToActOnWithoutADocument()
    {
        for (QAction *a : {m_actions->previousFrame, m_actions->nextFrame, m_actions->firstFrame, m_actions->lastFrame,
                           m_actions->playPause, m_actions->previousSequence, m_actions->nextSequence})
            QVERIFY2(!a->isEnabled(), qPrintable(a->objectName()));
        QVERIFY(!m_actions->registry->run(QStringLiteral("frame/next")));
        QVERIFY(!m_actions->registry->run(QStringLiteral("no/such-command")));
    }

    void frameCommandsFollowTheFrame()
    {
        testing::openDemo(m_context);
        QVERIFY(m_actions->nextSequence->isEnabled()); // a document with sequences, none shown
        testing::makeCurrent(m_context, 0);
        m_context.setCurrentFrame(0);
        QVERIFY(!m_actions->previousFrame->isEnabled()); // at the first frame
        QVERIFY(m_actions->nextFrame->isEnabled());
        QVERIFY(m_actions->lastFrame->isEnabled());
        QVERIFY(m_actions->playPause->isEnabled());

        QVERIFY(!m_actions->registry->run(QStringLiteral("frame/previous")));
        QCOMPARE(m_context.currentFrame(), 0);
        m_actions->nextFrame->trigger();
        QCOMPARE(m_context.currentFrame(), 1);
        QVERIFY(m_actions->previousFrame->isEnabled());
        m_actions->lastFrame->trigger();
        const int last = m_context.document()->sequence(0).frameCount - 1;
        QCOMPARE(m_context.currentFrame(), last);
        QVERIFY(!m_actions->nextFrame->isEnabled());
        QVERIFY(!m_actions->registry->run(QStringLiteral("frame/next")));
        QCOMPARE(m_context.currentFrame(), last);
        m_actions->firstFrame->trigger();
        QCOMPARE(m_context.currentFrame(), 0);
    }

    void sequenceCommandsLoadThroughTheContext()
    {
        QVERIFY(!m_actions->previousSequence->isEnabled()); // the first sequence
        QVERIFY(m_actions->nextSequence->isEnabled());
        QSignalSpy requested(&m_context, &StudioContext::sequenceRequested);
        QSignalSpy ended(&m_context, &StudioContext::sequenceLoadEnded);
        // Two presses while the first still loads: the second supersedes it.
        m_actions->nextSequence->trigger();
        m_actions->nextSequence->trigger();
        QCOMPARE(requested.count(), 2);
        QCOMPARE(requested.at(1).at(0).toInt(), 2);
        QCOMPARE(m_context.requestedSequence(), 2);
        QCOMPARE(m_context.currentSequence(), 0); // not before its media arrive
        QVERIFY(m_actions->previousSequence->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!ended.isEmpty() && ended.last().at(0).toBool(), 60000);
        QCOMPARE(m_context.currentSequence(), 2);
        QCOMPARE(m_context.requestedSequence(), 2);
        QCOMPARE(m_context.media()->sequenceId, QString::fromStdString(m_context.document()->sequence(2).id));
        QCOMPARE(m_context.currentFrame(), 0);
        QVERIFY(m_context.media()->frameCount() > 0);
        // The superseded load ended silently, without reaching the views; the last sequence has
        // no next.
        QCOMPARE(ended.count(), 1);
        m_context.selectSequence(m_context.document()->sequenceCount() - 1);
        QTRY_COMPARE_WITH_TIMEOUT(m_context.currentSequence(), m_context.document()->sequenceCount() - 1, 60000);
        QVERIFY(!m_actions->nextSequence->isEnabled());
        QVERIFY(!m_actions->registry->run(QStringLiteral("sequence/next")));
    }

    void aNameIsRegisteredOnce()
    {
        QVERIFY_THROWS_EXCEPTION(Error, m_actions->registry->add({QStringLiteral("frame/next"), QStringLiteral("Again"),
                                                                  {}, QStyle::SP_CustomBase, nullptr, nullptr}));
        QCOMPARE(m_actions->registry->action(QStringLiteral("frame/next")), m_actions->nextFrame);
    }

    // A panel's own actions are commands too: the timeline's Align validates on the sequence shown
    // and the task running, and runs through the registry.
    void thePanelsActionsValidateAsCommands()
    {
        TimelinePanel timeline;
        timeline.attach(&m_context);
        m_context.playback()->setAudioEnabled(false);
        m_context.selectSequence(0);
        QTRY_COMPARE_WITH_TIMEOUT(m_context.currentSequence(), 0, 60000);
        QAction *align = m_actions->registry->action(QStringLiteral("timeline/align"));
        QVERIFY(align);
        QVERIFY(align->isEnabled()); // a transcript to align
        QVERIFY(!m_actions->registry->action(QStringLiteral("timeline/realign-selection"))->isEnabled()); // no selection
        QVERIFY(m_actions->registry->run(QStringLiteral("timeline/align")));
        QVERIFY(!align->isEnabled()); // one alignment at a time
        QVERIFY(!m_actions->registry->run(QStringLiteral("timeline/align")));
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000);
        QTRY_VERIFY(align->isEnabled());
    }

    // A command goes with the object whose functions it runs: no action left to call into it.
    void aCommandGoesWithItsOwner()
    {
        auto *owner = new QObject;
        int runs = 0;
        QAction *action = m_actions->registry->add({QStringLiteral("test/owned"), QStringLiteral("Owned"), {},
                                                    QStyle::SP_CustomBase, nullptr, [&runs](StudioContext &) { ++runs; }},
                                                   owner);
        QVERIFY(m_actions->registry->run(QStringLiteral("test/owned")));
        QCOMPARE(runs, 1);
        QSignalSpy gone(action, &QObject::destroyed);
        delete owner;
        QCOMPARE(gone.count(), 1);
        QVERIFY(!m_actions->registry->action(QStringLiteral("test/owned")));
        QVERIFY(!m_actions->registry->run(QStringLiteral("test/owned")));
        m_actions->registry->revalidate();
        QCOMPARE(runs, 1);
    }

    void cleanupTestCase()
    {
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000);
    }
};

QTEST_MAIN(TestStudioCommands)
#include "tst_studiocommands.moc"
