// An alignment cut into utterances at its pauses (project/UtteranceSplit.h): cuts at pauses once
// an utterance is long enough, keeps a margin of silence, never overlaps, snaps to video frames,
// leaves out long silences and cuts a stretch without a long pause at its widest gap.
#include "project/UtteranceSplit.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

std::vector<Interval> spoken(const Tier &words)
{
    std::vector<Interval> out;
    for (const Interval &i : words.intervals)
        if (!PhoneSet::isSilence(i.label))
            out.push_back(i);
    return out;
}

} // namespace

class TestUtteranceSplit : public QObject
{
    Q_OBJECT
private slots:
    void pausesAndLimits()
    {
        // Words of 0.4 s; pauses of 0.5 s after "c" and "f", 0.1 s elsewhere.
        Tier words{"words", {}};
        Tier phones{"phones", {}};
        double t = 0.0;
        auto add = [&](const std::string &label, double length) {
            words.intervals.push_back(Interval{t, t + length, label, false});
            phones.intervals.push_back(Interval{t, t + length, label == "sil" ? "sil" : "AH", false});
            t += length;
        };
        add("sil", 1.0);
        const std::vector<std::string> labels{"a", "b", "c", "d", "e", "f", "g", "h", "i"};
        for (const std::string &w : labels) {
            add(w, 0.4);
            add("sil", w == "c" || w == "f" ? 0.5 : 0.1);
        }
        add("sil", 3.0);
        UtteranceSplitOptions options;
        options.shortest = 1.0;
        options.frames = lipsync::FrameClock::uniform(25.0, int(std::ceil(t * 25.0)));
        const std::vector<UtteranceSpan> spans = lipsync::splitAtPauses(words, phones, t, options);
        QCOMPARE(int(spans.size()), 3);
        QCOMPARE(spans[0].transcript, std::string("a b c"));
        QCOMPARE(spans[1].transcript, std::string("d e f"));
        QCOMPARE(spans[2].transcript, std::string("g h i"));
        for (size_t k = 0; k < spans.size(); ++k) {
            const UtteranceSpan &s = spans[k];
            QVERIFY(std::abs(s.start * 25.0 - std::round(s.start * 25.0)) < 1e-6);
            QVERIFY(std::abs(s.end * 25.0 - std::round(s.end * 25.0)) < 1e-6);
            if (k > 0)
                QVERIFY(s.start >= spans[k - 1].end - 1e-9);
            // The margin of silence either side, half the pause at most; not the long silences.
            const std::vector<Interval> w = spoken(s.words);
            QVERIFY(w.front().start > 0.1 && w.front().start <= 0.3);
            QVERIFY(s.words.intervals.back().end - w.back().end <= 0.3);
            QCOMPARE(s.words.intervals.front().start, 0.0);
            QVERIFY(std::abs(s.words.intervals.back().end - (s.end - s.start)) < 1e-9);
            QCOMPARE(s.phones.intervals.back().end, s.words.intervals.back().end);
        }
        // Too long without a pause: cut at the widest gap before it.
        options.longest = 2.5;
        options.minimumPause = 1.0;
        const std::vector<UtteranceSpan> forced = lipsync::splitAtPauses(words, phones, t, options);
        QVERIFY(forced.size() >= 3);
        QCOMPARE(forced[0].transcript, std::string("a b c"));
        for (const UtteranceSpan &s : forced)
            QVERIFY2(s.end - s.start <= 2.5 + 2 * options.margin + 0.05, s.transcript.c_str());
    }
};

QTEST_GUILESS_MAIN(TestUtteranceSplit)
#include "tst_utterancesplit.moc"
