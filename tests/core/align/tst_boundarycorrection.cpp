// The word-boundary correction (align/BoundaryCorrection) and its place in the aligner model:
//  - an alignment's boundaries are found with their kind, words and phones, and scored against a
//    reference (a junction against both the left word's end and the right word's start);
//  - learning recovers offsets planted per word pair, keeps none when correcting cannot help, and
//    backs off to the phones that meet for a word pair it has not seen;
//  - applying moves word and phone tiers together, stops a frame short of the neighbouring
//    phones' far ends, and keeps the boundaries it is told to keep;
//  - the model file keeps the correction exactly (version 2; version 1 without one), and damaged
//    correction lines are errors naming the file and line;
//  - calibrate() on the demo's GRID clips and their .align timings, with the shipped model: the
//    recordings without timing or with other words are left out, one with a breath is used, and the correction learned
//    brings the clips' boundaries closer to their timings.
#include "align/AcousticModel.h"
#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/BoundaryCorrection.h"
#include "align/ForcedAligner.h"
#include "io/Transcript.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <random>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";
const std::string kShipped = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";

Tier tier(const char *name, std::initializer_list<Interval> intervals)
{
    return Tier{name, std::vector<Interval>(intervals)};
}

// "bin blue" then a pause, "at", a pause: one onset, one junction, offsets and another onset.
AlignmentResult binBlueAt()
{
    AlignmentResult r;
    r.words = tier("words", {{0.0, 0.3, "sil"}, {0.3, 0.6, "bin"}, {0.6, 0.9, "blue"}, {0.9, 1.2, "sil"},
                             {1.2, 1.4, "at"}, {1.4, 1.6, "sil"}});
    r.phones = tier("phones", {{0.0, 0.3, "sil"}, {0.3, 0.4, "B"}, {0.4, 0.5, "IH"}, {0.5, 0.6, "N"},
                               {0.6, 0.7, "B"}, {0.7, 0.8, "L"}, {0.8, 0.9, "UW"}, {0.9, 1.2, "sil"},
                               {1.2, 1.3, "AE"}, {1.3, 1.4, "T"}, {1.4, 1.6, "sil"}});
    return r;
}

Tier binBlueAtReference()
{
    return tier("words", {{0.0, 0.28, "sil"}, {0.28, 0.62, "bin"}, {0.64, 0.9, "blue"}, {0.9, 1.25, "sp"},
                          {1.25, 1.38, "at"}, {1.38, 1.6, "sil"}});
}

BoundaryError boundary(BoundaryKind kind, const char *lw, const char *rw, const char *lp, const char *rp, double error)
{
    return {kind, lw, rw, lp, rp, {error}};
}

void checkContiguous(const Tier &t)
{
    for (size_t i = 0; i < t.intervals.size(); ++i) {
        QVERIFY2(t.intervals[i].end > t.intervals[i].start, t.intervals[i].label.c_str());
        if (i > 0)
            QCOMPARE(t.intervals[i].start, t.intervals[i - 1].end);
    }
}

} // namespace

class TestBoundaryCorrection : public QObject
{
    Q_OBJECT

private slots:
    void boundariesAreScoredAgainstTheReference()
    {
        const std::vector<BoundaryError> e = BoundaryCorrection::errors(binBlueAt(), binBlueAtReference());
        QCOMPARE(e.size(), size_t(5));
        QCOMPARE(int(e[0].kind), int(BoundaryKind::Onset));
        QCOMPARE(e[0].leftWord, std::string("sil"));
        QCOMPARE(e[0].rightWord, std::string("bin"));
        QCOMPARE(e[0].rightPhone, std::string("B"));
        QCOMPARE(e[0].errors.size(), size_t(1));
        QVERIFY(std::abs(e[0].errors[0] - 0.02) < 1e-12);
        QCOMPARE(int(e[1].kind), int(BoundaryKind::Junction));
        QCOMPARE(e[1].leftWord + "|" + e[1].rightWord, std::string("bin|blue"));
        QCOMPARE(e[1].leftPhone + "|" + e[1].rightPhone, std::string("N|B"));
        QCOMPARE(e[1].errors.size(), size_t(2)); // against bin's end (0.62) and blue's start (0.64)
        QVERIFY(std::abs(e[1].errors[0] + 0.02) < 1e-12 && std::abs(e[1].errors[1] + 0.04) < 1e-12);
        QVERIFY(std::abs(e[1].target() + 0.03) < 1e-12);
        QCOMPARE(int(e[2].kind), int(BoundaryKind::Offset));
        QCOMPARE(e[2].leftPhone + "|" + e[2].rightPhone + "|" + e[2].rightWord, std::string("UW|sil|sil"));
        QVERIFY(std::abs(e[2].errors[0]) < 1e-12);
        QVERIFY(std::abs(e[3].errors[0] + 0.05) < 1e-12); // "at" starts 50 ms early
        QVERIFY(std::abs(e[4].errors[0] - 0.02) < 1e-12);
        // Other words than the alignment's: nothing to score.
        Tier other = binBlueAtReference();
        other.intervals.erase(other.intervals.begin() + 4);
        QVERIFY(BoundaryCorrection::errors(binBlueAt(), other).empty());
    }

    void learningRecoversPlantedOffsetsAndBacksOff()
    {
        // 100 recordings, each with an onset of "set" 40 ms late, a junction "bin red" 30 ms early,
        // a junction "lay red" 20 ms early and an offset of "now" on time, ±8 ms of noise.
        std::mt19937 random(7);
        std::uniform_real_distribution<double> noise(-0.008, 0.008);
        std::vector<std::vector<BoundaryError>> recordings(100);
        for (auto &r : recordings) {
            r.push_back(boundary(BoundaryKind::Onset, "sil", "set", "sil", "S", 0.040 + noise(random)));
            r.push_back(boundary(BoundaryKind::Junction, "bin", "red", "N", "R", -0.030 + noise(random)));
            r.push_back(boundary(BoundaryKind::Junction, "lay", "red", "EY", "R", -0.020 + noise(random)));
            r.push_back(boundary(BoundaryKind::Offset, "now", "sil", "AW", "sil", noise(random)));
        }
        BoundaryCorrectionReport report;
        const BoundaryCorrection c = BoundaryCorrection::learn(recordings, {}, &report);
        QVERIFY(!c.empty());
        QCOMPARE(report.utterances, 100);
        QCOMPARE(report.boundaries, 400);
        QCOMPARE(report.minimumCount, 40); // every group is large: the most conservative candidate ties
        QVERIFY2(report.withinBefore < 0.9 && report.withinAfter == 1.0,
                 qPrintable(QString("%1 -> %2").arg(report.withinBefore).arg(report.withinAfter)));
        QVERIFY(std::abs(c.offset(recordings[0][0]) - 0.040) < 0.004);
        QVERIFY(std::abs(c.offset(recordings[0][1]) + 0.030) < 0.004);
        QVERIFY(std::abs(c.offset(recordings[0][2]) + 0.020) < 0.004);
        QVERIFY(std::abs(c.offset(recordings[0][3])) < 0.004);
        // An unseen word pair across the same phones takes theirs; an unseen onset the onsets'.
        QVERIFY(std::abs(c.offset(boundary(BoundaryKind::Junction, "pin", "red", "N", "R", 0)) + 0.030) < 0.004);
        QVERIFY(std::abs(c.offset(boundary(BoundaryKind::Junction, "x", "y", "K", "R", 0)) + 0.025) < 0.006);
        QVERIFY(std::abs(c.offset(boundary(BoundaryKind::Onset, "sil", "zoo", "sil", "Z", 0)) - 0.040) < 0.004);
    }

    void noCorrectionWhereItCannotHelp()
    {
        std::mt19937 random(11);
        std::uniform_real_distribution<double> noise(-0.02, 0.02);
        std::vector<std::vector<BoundaryError>> recordings(50);
        for (auto &r : recordings)
            r.push_back(boundary(BoundaryKind::Junction, "bin", "red", "N", "R", noise(random)));
        BoundaryCorrectionReport report;
        const BoundaryCorrection c = BoundaryCorrection::learn(recordings, {}, &report);
        QVERIFY(c.empty());
        QCOMPARE(report.minimumCount, 0);
        QCOMPARE(report.withinBefore, 1.0);
        QCOMPARE(report.withinAfter, 1.0);
        QVERIFY(BoundaryCorrection::learn({}).empty());
    }

    void applyMovesBothTiersAndKeepsWhatItIsTold()
    {
        BoundaryCorrection c;
        c.setMinimumCount(5);
        c.addLine("junction words bin blue 0.030000 10");
        c.addLine("onset phone AE -0.500000 10"); // far beyond the phones: stops a frame short
        AlignmentResult r = binBlueAt();
        c.apply(r);
        checkContiguous(r.words);
        checkContiguous(r.phones);
        QVERIFY(std::abs(r.words.intervals[1].end - 0.57) < 1e-9);
        QVERIFY(std::abs(r.phones.intervals[3].end - 0.57) < 1e-9); // N of "bin"
        QVERIFY(std::abs(r.phones.intervals[4].start - 0.57) < 1e-9); // B of "blue"
        QVERIFY(std::abs(r.words.intervals[4].start - 1.29) < 1e-9); // AE ends at 1.3: one frame before
        QVERIFY(std::abs(r.phones.intervals[8].start - 1.29) < 1e-9);
        QCOMPARE(r.words.intervals[0].end, 0.3); // no entry for this onset
        // Kept boundaries stay.
        AlignmentResult kept = binBlueAt();
        c.apply(kept, {0.6});
        QCOMPARE(kept.words.intervals[1].end, 0.6);
        QVERIFY(std::abs(kept.words.intervals[4].start - 1.29) < 1e-9);
        // Upper-case words in the alignment match the lower-case groups.
        AlignmentResult upper = binBlueAt();
        upper.words.intervals[1].label = "BIN";
        c.apply(upper);
        QVERIFY(std::abs(upper.words.intervals[1].end - 0.57) < 1e-9);
    }

    void modelFilesKeepTheCorrection()
    {
        AcousticModel model(MfccOptions{}, CepstralNormalization::Mean, Eigen::VectorXf::Zero(39),
                            Eigen::VectorXf::Ones(39));
        QVERIFY(model.text().rfind("lipsync-aligner 1\n", 0) == 0);
        BoundaryCorrection c;
        c.setMinimumCount(5);
        c.addLine("junction words bin blue -0.030000 10");
        c.addLine("onset 0.012500 400");
        c.addLine("offset phones AW sil 0.040000 104");
        model.setBoundaryCorrection(c);
        const std::string text = model.text();
        QVERIFY(text.rfind("lipsync-aligner 2\n", 0) == 0);
        const AcousticModel read = AcousticModel::parse(text, "m.aligner");
        QVERIFY(read.boundaryCorrection() == c);
        QCOMPARE(read.boundaryCorrection().minimumCount(), 5);
        QCOMPARE(read.text(), text);
        // Damaged correction lines name the file and line.
        const size_t at = text.find("boundaries minimum");
        for (const auto &[bad, why] : std::vector<std::pair<std::string, std::string>>{
                 {"boundaries minimum 5 entries 4\n", "end of file"},
                 {"boundaries minimum 0 entries 3\n", "boundaries minimum M entries N"},
                 {"boundaries minimum 5 entries 3\nb junction words bin blue x 10\n", "offset in seconds"},
                 {"boundaries minimum 5 entries 3\nb sideways 0.1 10\n", "unknown boundary kind"},
                 {"boundaries minimum 5 entries 3\nb onset 2.5 10\n", "out of range"},
                 {"boundaries minimum 5 entries 3\nb onset 0.1 10\nb onset 0.2 10\n", "given twice"}}) {
            std::string damaged = text.substr(0, at) + bad;
            if (why != "end of file" && why != "given twice")
                damaged += "b onset 0.1 10\nb offset 0.1 10\n";
            else if (why == "given twice")
                damaged += "b offset 0.1 10\n";
            try {
                AcousticModel::parse(damaged, "m.aligner");
                QFAIL(qPrintable(QString::fromStdString("accepted: " + bad)));
            } catch (const Error &e) {
                const std::string what = e.what();
                QVERIFY2(what.find("m.aligner") != std::string::npos && what.find("line") != std::string::npos
                             && what.find(why) != std::string::npos,
                         e.what());
            }
        }
        // A version-1 file with a correction section is not read as one.
        std::string v1 = text;
        v1.replace(0, std::string("lipsync-aligner 2").size(), "lipsync-aligner 1");
        QVERIFY(AcousticModel::parse(v1, "m.aligner").boundaryCorrection().empty());
    }

    // The demo's ten GRID clips against their .align timings, the shipped model, two folds.
    void calibratesOnRealClips()
    {
        const AcousticModel model = AcousticModel::load(kShipped);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        std::vector<TrainingUtterance> utterances;
        for (const char *id : {"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p", "pbav2n", "pgwe6n", "pwbk1s",
                               "sbwo1s", "srbu6n"}) {
            const Transcript t = readTranscript(kDemo + id + ".align");
            const PreparedUtterance u = prepareUtterance(id, kDemo + id + ".mpg", t.words, model, lexicon);
            utterances.push_back({id, u.features, u.pronunciations, t.timing});
        }
        utterances.push_back(utterances[0]);
        utterances.back().reference.intervals.erase(utterances.back().reference.intervals.begin() + 1); // other words
        utterances.push_back(utterances[1]);
        utterances.back().reference = {};                          // no timing: not used
        {
            // A breath in the leading silence: a word of the transcript (io/Transcript keeps it),
            // pronounced and aligned, a pause for the boundaries.
            const char *id = "bwbg8n";
            Transcript t = readTranscript(kDemo + id + ".align");
            std::vector<Interval> &iv = t.timing.intervals;
            QVERIFY(!iv.empty() && PhoneSet::isSilence(iv.front().label));
            const double start = iv.front().end;
            iv.front().end = start / 3;
            iv.insert(iv.begin() + 1, {{start / 3, 2 * start / 3, "br"}, {2 * start / 3, start, "sil"}});
            std::vector<std::string> words{"br"};
            words.insert(words.end(), t.words.begin(), t.words.end());
            const PreparedUtterance u = prepareUtterance(id, kDemo + id + ".mpg", words, model, lexicon);
            utterances.push_back({id, u.features, u.pronunciations, t.timing});
        }
        BoundaryCorrection::Options options;
        options.minimumCounts = {3, 6};
        options.folds = 2;
        BoundaryCorrectionReport report;
        const BoundaryCorrection c = AlignerTrainer::calibrate(model, utterances, options, &report);
        QCOMPARE(report.utterances, 11);
        QCOMPARE(report.skipped, 1);
        QCOMPARE(report.boundaries, 132); // 6 words a clip: 2 silence edges and 5 junctions of 2
        QVERIFY(report.withinBefore > 0.5 && report.withinBefore <= 1.0);
        QVERIFY(report.withinAfter >= report.withinBefore);
        QCOMPARE(c.empty(), report.minimumCount == 0);
        QVERIFY2(!c.empty(), "the shipped model's offsets on GRID are systematic: a correction is learned");
        // The learned correction brings the clips' own boundaries closer.
        double before = 0, after = 0;
        for (size_t i = 0; i < 10; ++i) {
            const TrainingUtterance &u = utterances[i];
            std::vector<std::string> words;
            for (const Interval &w : u.reference.intervals)
                if (w.label != "sil" && w.label != "sp")
                    words.push_back(w.label);
            AlignmentResult r = ForcedAligner(model).align(u.features, words, u.pronunciations);
            for (const BoundaryError &b : BoundaryCorrection::errors(r, u.reference))
                for (double e : b.errors)
                    before += std::abs(e);
            c.apply(r);
            for (const BoundaryError &b : BoundaryCorrection::errors(r, u.reference))
                for (double e : b.errors)
                    after += std::abs(e);
        }
        QVERIFY2(after < before, qPrintable(QString("%1 -> %2").arg(before).arg(after)));
    }
};

QTEST_GUILESS_MAIN(TestBoundaryCorrection)
#include "tst_boundarycorrection.moc"
