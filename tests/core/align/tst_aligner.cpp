// Monophone HMM training and forced alignment.
//  - Synthetic speech whose "phones" are tones and noise, with known boundaries: training from a
//    flat start recovers them, and the log-likelihood never decreases between iterations at a
//    fixed mixture count (EM; the variance floor is the exact constrained maximiser).
//  - Model files round-trip; bad model files are named with their line.
//  - Real speech: the GRID demo clips (resources/demo/media) — training likelihood on three
//    clips, and the shipped model (resources/aligner/grid-s1.aligner, trained on all 400 GRID s1
//    clips, these among them: a check that it loads and aligns, not of its accuracy on unseen
//    clips, which BM_EvalGridWordsKFold measures) aligns a demo clip within tolerance of GRID's
//    own .align timings.
#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
#include "align/Realignment.h"
#include "io/AudioDecoder.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <fstream>
#include <random>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";
const std::string kShippedModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";

Pronunciation p(const char *phones)
{
    return PronunciationDictionary::parse(phones);
}

struct Synthetic
{
    std::vector<float> samples;
    std::vector<std::string> words;
    std::vector<double> wordStarts, wordEnds;
};

// "Phones": AA = 300 Hz + 900 Hz tones, M = 1800 Hz tone, S = white noise, sil = faint noise.
Synthetic synthesize(std::mt19937 &rng, const std::map<std::string, std::string> &lexicon)
{
    std::uniform_real_distribution<double> duration(0.08, 0.2), pause(0.0, 0.15);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::uniform_int_distribution<int> pick(0, int(lexicon.size()) - 1);
    Synthetic s;
    auto append = [&](const std::string &phone, double seconds) {
        const size_t n = size_t(seconds * 16000);
        for (size_t i = 0; i < n; ++i) {
            const double t = double(s.samples.size()) / 16000;
            double v = 0.001 * noise(rng);
            if (phone == "AA")
                v += 0.3 * std::sin(2 * M_PI * 300 * t) + 0.1 * std::sin(2 * M_PI * 900 * t);
            else if (phone == "M")
                v += 0.2 * std::sin(2 * M_PI * 1800 * t);
            else if (phone == "S")
                v += 0.1 * noise(rng);
            s.samples.push_back(float(v));
        }
    };
    append("sil", 0.25);
    const int count = 2 + int(rng() % 2);
    for (int w = 0; w < count; ++w) {
        auto it = lexicon.begin();
        std::advance(it, pick(rng));
        s.words.push_back(it->first);
        s.wordStarts.push_back(double(s.samples.size()) / 16000);
        std::istringstream phones(it->second);
        std::string phone;
        while (phones >> phone)
            append(phone, duration(rng));
        s.wordEnds.push_back(double(s.samples.size()) / 16000);
        if (w + 1 < count)
            append("sil", pause(rng) < 0.05 ? 0.0 : pause(rng));
    }
    append("sil", 0.25);
    return s;
}

const std::map<std::string, std::string> kWords{{"as", "AA S"}, {"ma", "M AA"}, {"sam", "S AA M"}, {"mass", "M AA S"}};

std::vector<std::vector<Pronunciation>> pronounce(const std::vector<std::string> &words)
{
    std::vector<std::vector<Pronunciation>> out;
    for (const std::string &w : words)
        out.push_back({p(kWords.at(w).c_str())});
    return out;
}

TrainerOptions smallOptions()
{
    TrainerOptions o;
    o.mixtureSchedule = {1, 2};
    o.firstStageIterations = 5;
    o.iterationsPerStage = 3;
    return o;
}

// A 16-bit PCM WAV file.
void writeWav(const std::string &path, const std::vector<int16_t> &interleaved, int rate, int channels)
{
    std::ofstream f(path, std::ios::binary);
    auto u32 = [&](uint32_t v) { f.write(reinterpret_cast<const char *>(&v), 4); };
    auto u16 = [&](uint16_t v) { f.write(reinterpret_cast<const char *>(&v), 2); };
    const uint32_t bytes = uint32_t(interleaved.size() * 2);
    f.write("RIFF", 4);
    u32(36 + bytes);
    f.write("WAVEfmt ", 8);
    u32(16), u16(1), u16(uint16_t(channels)), u32(uint32_t(rate)), u32(uint32_t(rate * channels * 2)),
        u16(uint16_t(channels * 2)), u16(16);
    f.write("data", 4);
    u32(bytes);
    f.write(reinterpret_cast<const char *>(interleaved.data()), bytes);
}

} // namespace

class TestAligner : public QObject
{
    Q_OBJECT
private slots:
    void syntheticTrainingRecoversBoundaries()
    {
        std::mt19937 rng(11);
        const AcousticModel features = featureModel(smallOptions());
        std::vector<TrainingUtterance> train;
        for (int i = 0; i < 24; ++i) {
            const Synthetic s = synthesize(rng, kWords);
            train.push_back({"u" + std::to_string(i), features.features(s.samples), pronounce(s.words)});
        }
        Feedback feedback;
        std::vector<double> reported;
        feedback.onIteration = [&](int, double ll) { reported.push_back(ll); };
        TrainingReport report;
        const AcousticModel model = AlignerTrainer::train(train, smallOptions(), feedback, &report);
        QCOMPARE(reported.size(), size_t(8));
        QCOMPARE(report.logLikelihoodPerFrame, reported);
        QVERIFY(report.failedUtterances.empty());
        // EM: non-decreasing within each mixture stage (iterations 0-4 and 5-7).
        for (size_t i = 1; i < reported.size(); ++i)
            if (i != 5)
                QVERIFY2(reported[i] >= reported[i - 1] - 1e-4,
                         qPrintable(QStringLiteral("iteration %1: %2 < %3").arg(i).arg(reported[i]).arg(reported[i - 1])));
        QVERIFY(reported.back() > reported.front() + 1.0);

        // Held-out utterances: word boundaries within 30 ms.
        const ForcedAligner aligner(model);
        int good = 0, total = 0;
        for (int i = 0; i < 6; ++i) {
            const Synthetic s = synthesize(rng, kWords);
            const AlignmentResult r = aligner.align(model.features(s.samples), s.words, pronounce(s.words),
                                                    double(s.samples.size()) / 16000);
            std::vector<Interval> words;
            for (const Interval &w : r.words.intervals)
                if (w.label != "sil")
                    words.push_back(w);
            QCOMPARE(words.size(), s.words.size());
            for (size_t w = 0; w < words.size(); ++w) {
                QCOMPARE(words[w].label, s.words[w]);
                good += std::abs(words[w].start - s.wordStarts[w]) <= 0.03;
                good += std::abs(words[w].end - s.wordEnds[w]) <= 0.03;
                total += 2;
            }
            // Phone tier tiles the utterance.
            QCOMPARE(r.phones.intervals.front().start, 0.0);
            for (size_t k = 1; k < r.phones.intervals.size(); ++k)
                QCOMPARE(r.phones.intervals[k].start, r.phones.intervals[k - 1].end);
        }
        QVERIFY2(good >= total * 9 / 10, qPrintable(QStringLiteral("%1 of %2 boundaries within 30 ms").arg(good).arg(total)));
    }

    void transcriptThatDoesNotFit()
    {
        std::mt19937 rng(3);
        const AcousticModel model = featureModel(smallOptions());
        std::vector<float> samples(1600, 0.01f); // 0.1 s
        const std::vector<std::string> words(10, "sam");
        try {
            ForcedAligner(model).align(model.features(samples), words, pronounce(words));
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY(std::string(e.what()).find("does not fit") != std::string::npos);
        }
        // In training the utterance is reported and skipped, the others train.
        std::vector<TrainingUtterance> train;
        for (int i = 0; i < 4; ++i) {
            const Synthetic s = synthesize(rng, kWords);
            train.push_back({"ok" + std::to_string(i), model.features(s.samples), pronounce(s.words)});
        }
        train.push_back({"short", model.features(samples), pronounce(words)});
        TrainerOptions o = smallOptions();
        o.mixtureSchedule = {1};
        o.firstStageIterations = 2;
        Feedback feedback;
        TrainingReport report;
        AlignerTrainer::train(train, o, feedback, &report);
        QCOMPARE(report.failedUtterances, std::vector<std::string>{"short"});
    }

    void modelFileRoundTrip()
    {
        std::mt19937 rng(5);
        const AcousticModel features = featureModel(smallOptions());
        std::vector<TrainingUtterance> train;
        for (int i = 0; i < 6; ++i) {
            const Synthetic s = synthesize(rng, kWords);
            train.push_back({"u", features.features(s.samples), pronounce(s.words)});
        }
        TrainerOptions o = smallOptions();
        o.firstStageIterations = 2;
        o.iterationsPerStage = 1;
        o.normalization = CepstralNormalization::MeanAndVariance;
        Feedback feedback;
        const AcousticModel model = AlignerTrainer::train(train, o, feedback);
        QTemporaryDir dir;
        const std::string path = dir.filePath("m.aligner").toStdString();
        model.save(path);
        const AcousticModel back = AcousticModel::load(path);
        QCOMPARE(back.dimension(), 39);
        QCOMPARE(back.normalization(), CepstralNormalization::MeanAndVariance);
        {
            // CMVN: every coefficient has zero mean (static ones) and unit variance per utterance.
            std::mt19937 r2(9);
            const Eigen::MatrixXf n = back.features(synthesize(r2, kWords).samples);
            const Eigen::RowVectorXf mean = n.colwise().mean();
            const Eigen::RowVectorXf var = (n.rowwise() - mean).array().square().colwise().mean();
            QVERIFY(mean.head(13).cwiseAbs().maxCoeff() < 1e-3f);
            QVERIFY((var.array() - 1.0f).abs().maxCoeff() < 1e-3f);
        }
        QVERIFY(back.featureOptions() == model.featureOptions());
        const Eigen::MatrixXf f = model.features(std::vector<float>(8000, 0.01f));
        for (int j = 0; j < model.stateCount(); ++j) {
            QCOMPARE(back.state(j).size(), model.state(j).size());
            QVERIFY(std::abs(back.state(j).logLikelihood(f.data()) - model.state(j).logLikelihood(f.data())) < 1e-2);
            QVERIFY(std::abs(back.selfLoop(j) - model.selfLoop(j)) < 1e-6);
        }
        // Bad files name the file and line.
        {
            std::ofstream out(path);
            out << "lipsync-aligner 1\nfeatures 16000 0.025 0.01 0.97 26 12 22 2 1\ndimension 39\nfloor 1 2\n";
        }
        try {
            AcousticModel::load(path);
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.field(), std::string("line 4"));
            QCOMPARE(e.file(), path);
        }
        {
            std::ofstream out(path);
            out << "lipsync-aligner 7\n";
        }
        QVERIFY_THROWS_EXCEPTION(Error, AcousticModel::load(path));
    }

    void fuzzSeedsAreValidModels()
    {
        // The fuzz seeds of tests/data/fuzz/aligner (see its README) must stay loadable models, or
        // the fuzzer would only explore the error paths.
        const AcousticModel one = AcousticModel::load(LIPSYNC_TEST_DATA "/fuzz/aligner/grid-s1-dim1.aligner");
        QCOMPARE(one.dimension(), 1);
        const AcousticModel two = AcousticModel::load(LIPSYNC_TEST_DATA "/fuzz/aligner/tiny-d2-m2.aligner");
        QCOMPARE(two.dimension(), 2);
        QCOMPARE(two.stateCount(), PhoneSet::kCount * AcousticModel::kStatesPerPhone);
        QCOMPARE(two.state(AcousticModel::stateIndex(0, 0)).size(), 2);
        QCOMPARE(two.state(AcousticModel::stateIndex(0, 1)).size(), 1);
    }

    void gridDemoTrainingLikelihoodIncreases()
    {
        TrainerOptions o;
        o.mixtureSchedule = {1};
        o.firstStageIterations = 3;
        const AcousticModel features = featureModel(o);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        std::vector<TrainingUtterance> train;
        for (const char *id : {"bbaf2n", "bgin3a", "bwbg8n"}) {
            const Transcript t = readTranscript(kDemo + id + ".align");
            PreparedUtterance u = prepareUtterance(id, kDemo + id + ".mpg", t.words, features, lexicon);
            QVERIFY(u.duration > 2.9 && u.duration < 3.1);
            train.push_back({id, u.features, u.pronunciations});
        }
        Feedback feedback;
        TrainingReport report;
        AlignerTrainer::train(train, o, feedback, &report);
        QCOMPARE(report.logLikelihoodPerFrame.size(), size_t(3));
        for (size_t i = 1; i < 3; ++i)
            QVERIFY(report.logLikelihoodPerFrame[i] >= report.logLikelihoodPerFrame[i - 1] - 1e-4);
    }

    void shippedModelAlignsGridDemoClip()
    {
        const AcousticModel model = AcousticModel::load(kShippedModel);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        int good = 0, total = 0;
        for (const char *id : {"bbaf2n", "lrik4p"}) {
            const Transcript t = readTranscript(kDemo + id + ".align");
            const PreparedUtterance u = prepareUtterance(id, kDemo + id + ".mpg", t.words, model, lexicon);
            const AlignmentResult r = ForcedAligner(model).align(u.features, u.words, u.pronunciations, u.duration);
            std::vector<Interval> ref, hyp;
            for (const Interval &i : t.timing.intervals)
                if (i.label != "sil" && i.label != "sp")
                    ref.push_back(i);
            for (const Interval &i : r.words.intervals)
                if (i.label != "sil")
                    hyp.push_back(i);
            QCOMPARE(hyp.size(), ref.size());
            for (size_t w = 0; w < ref.size(); ++w) {
                QCOMPARE(hyp[w].label, ref[w].label);
                if (w > 0) {
                    good += std::abs(hyp[w].start - ref[w].start) <= 0.04 + 1e-6;
                    ++total;
                }
                if (w + 1 < ref.size()) {
                    good += std::abs(hyp[w].end - ref[w].end) <= 0.04 + 1e-6;
                    ++total;
                }
                // No gross errors, silence edges included (GRID's own timings are automatic too).
                QVERIFY(std::abs(hyp[w].start - ref[w].start) < 0.25);
                QVERIFY(std::abs(hyp[w].end - ref[w].end) < 0.25);
            }
        }
        QVERIFY2(good >= total * 3 / 4, qPrintable(QStringLiteral("%1 of %2 inner word boundaries within 40 ms").arg(good).arg(total)));
    }

    // Constrained Viterbi: fixed word boundaries are hard constraints.
    void fixedBoundariesStayAndFreeOnesFollowTheUnconstrainedPath()
    {
        const AcousticModel model = AcousticModel::load(kShippedModel);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const Transcript t = readTranscript(kDemo + std::string("bbaf2n.align"));
        const PreparedUtterance u = prepareUtterance("bbaf2n", kDemo + "bbaf2n.mpg", t.words, model, lexicon);
        const ForcedAligner aligner(model);
        const AlignmentResult free = aligner.align(u.features, u.words, u.pronunciations, u.duration);
        auto spoken = [](const Tier &words) {
            std::vector<Interval> out;
            for (const Interval &i : words.intervals)
                if (i.label != "sil")
                    out.push_back(i);
            return out;
        };
        const std::vector<Interval> ref = spoken(free.words);
        QCOMPARE(ref.size(), u.words.size());

        // Constraints that agree with the free solution: the same path, boundary for boundary.
        const std::vector<FixedBoundary> agree{{1, FixedBoundary::Side::Start, ref[1].start},
                                               {3, FixedBoundary::Side::End, ref[3].end}};
        const AlignmentResult same = aligner.align(u.features, u.words, u.pronunciations, u.duration, agree);
        QCOMPARE(same.words, free.words);
        QCOMPARE(same.phones, free.phones);
        QCOMPARE(same.logLikelihood, free.logLikelihood);

        // Moved boundaries (a user's fix, off the 10 ms grid by 2 ms) stay exactly where put.
        const double start2 = ref[2].start + 0.062, end4 = ref[4].end - 0.048;
        const std::vector<FixedBoundary> moved{{2, FixedBoundary::Side::Start, start2},
                                               {4, FixedBoundary::Side::End, end4}};
        const AlignmentResult fixed = aligner.align(u.features, u.words, u.pronunciations, u.duration, moved);
        const std::vector<Interval> hyp = spoken(fixed.words);
        QCOMPARE(hyp.size(), ref.size());
        QCOMPARE(hyp[2].start, start2);
        QCOMPARE(hyp[4].end, end4);
        QVERIFY(fixed.logLikelihood < free.logLikelihood);
        // The phone tier agrees: a phone starts where word 2 starts and one ends where word 4 ends.
        bool phoneAtStart = false, phoneAtEnd = false;
        for (const Interval &p : fixed.phones.intervals) {
            phoneAtStart = phoneAtStart || p.start == start2;
            phoneAtEnd = phoneAtEnd || p.end == end4;
        }
        QVERIFY(phoneAtStart && phoneAtEnd);
        // Words far from the moved boundaries are where the free alignment put them.
        QCOMPARE(hyp[0].start, ref[0].start);
        QCOMPARE(hyp.back().end, ref.back().end);

        // Re-aligning stretches (core/align/Realignment): a user-fixed word stays as it is, the
        // free words around it meet it exactly, and with nothing fixed the result is the free path.
        {
            const Realignment all(free.words, free.phones,
                                  Realignment::freeStretches(free.words, free.phones, 0.0, u.duration));
            const AlignmentResult again = all.run(aligner, u.features, lexicon.pronounceAll(all.words()), u.duration);
            QCOMPARE(again.words, free.words);
            QCOMPARE(again.phones, free.phones);

            Tier words = free.words;
            int w = -1;
            for (int i = 0; i < int(words.intervals.size()); ++i)
                if (words.intervals[size_t(i)].label == u.words[2])
                    w = i;
            QVERIFY(w > 0);
            // The user moves the word's start 30 ms earlier, word and phone edge together.
            Interval &edited = words.intervals[size_t(w)];
            Tier phones = free.phones;
            for (std::size_t i = 1; i < phones.intervals.size(); ++i)
                if (phones.intervals[i].start == edited.start) {
                    phones.intervals[i].start -= 0.03;
                    phones.intervals[i - 1].end -= 0.03;
                }
            edited.start -= 0.03;
            edited.userEdited = true;
            words.intervals[size_t(w - 1)].end = edited.start;
            const auto stretches = Realignment::freeStretches(words, phones, 0.0, u.duration);
            QCOMPARE(int(stretches.size()), 2);
            const Realignment around(words, phones, stretches);
            QCOMPARE(int(around.fixed().size()), 4); // both edges of the word, and its neighbours' there

            const AlignmentResult r = around.run(aligner, u.features, lexicon.pronounceAll(around.words()), u.duration);
            QVERIFY(std::find(r.words.intervals.begin(), r.words.intervals.end(), edited) != r.words.intervals.end());
            for (std::size_t i = 1; i < r.words.intervals.size(); ++i)
                QCOMPARE(r.words.intervals[i].start, r.words.intervals[i - 1].end);
            for (std::size_t i = 1; i < r.phones.intervals.size(); ++i)
                QCOMPARE(r.phones.intervals[i].start, r.phones.intervals[i - 1].end);
            QCOMPARE(spoken(r.words).size(), u.words.size());
        }

        // Boundaries that leave no room for a word's phones are refused with a clear error.
        const std::vector<FixedBoundary> squeezed{{3, FixedBoundary::Side::Start, ref[3].start},
                                                  {3, FixedBoundary::Side::End, ref[3].start + 0.02}};
        QVERIFY_THROWS_EXCEPTION(Error, aligner.align(u.features, u.words, u.pronunciations, u.duration, squeezed));
        // A boundary of a word that is not there is an error too.
        QVERIFY_THROWS_EXCEPTION(Error, aligner.align(u.features, u.words, u.pronunciations, u.duration,
                                                      {{int(u.words.size()), FixedBoundary::Side::Start, 1.0}}));
    }

    void stereo48kHzClippedAudioStillAligns()
    {
        // The demo clip's audio at 48 kHz, stereo (right channel inverted-free copy at half gain),
        // 4x gain hard-clipped: the decoder resamples and mixes down, the aligner copes.
        const std::string id = "lrik4p";
        const AudioBuffer audio = AudioDecoder::decode(kDemo + id + ".mpg", 16000);
        std::vector<int16_t> pcm;
        for (size_t i = 0; i < audio.samples.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const float a = audio.samples[i], b = audio.samples[std::min(i + 1, audio.samples.size() - 1)];
                const float v = std::clamp(4.0f * (a + (b - a) * k / 3.0f), -1.0f, 1.0f);
                pcm.push_back(int16_t(v * 32767));
                pcm.push_back(int16_t(v * 16383));
            }
        QTemporaryDir dir;
        const std::string path = dir.filePath("loud.wav").toStdString();
        writeWav(path, pcm, 48000, 2);
        const AcousticModel model = AcousticModel::load(kShippedModel);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const Transcript t = readTranscript(kDemo + id + ".align");
        const PreparedUtterance u = prepareUtterance(id, path, t.words, model, lexicon);
        QVERIFY(std::abs(u.duration - audio.duration()) < 0.01);
        const AlignmentResult r = ForcedAligner(model).align(u.features, u.words, u.pronunciations, u.duration);
        std::vector<Interval> ref, hyp;
        for (const Interval &i : t.timing.intervals)
            if (i.label != "sil" && i.label != "sp")
                ref.push_back(i);
        for (const Interval &i : r.words.intervals)
            if (i.label != "sil")
                hyp.push_back(i);
        QCOMPARE(hyp.size(), ref.size());
        int good = 0;
        for (size_t w = 0; w < ref.size(); ++w)
            good += std::abs(hyp[w].start - ref[w].start) <= 0.06 && std::abs(hyp[w].end - ref[w].end) <= 0.06;
        QVERIFY2(good >= 4, qPrintable(QStringLiteral("%1 of 6 words within 60 ms").arg(good)));
    }

    void silentAudioIsAnError()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("silence.wav").toStdString();
        {
            // 1 s of 16-bit mono zeros at 16 kHz.
            std::ofstream f(path, std::ios::binary);
            auto u32 = [&](uint32_t v) { f.write(reinterpret_cast<const char *>(&v), 4); };
            auto u16 = [&](uint16_t v) { f.write(reinterpret_cast<const char *>(&v), 2); };
            f.write("RIFF", 4);
            u32(36 + 32000);
            f.write("WAVEfmt ", 8);
            u32(16), u16(1), u16(1), u32(16000), u32(32000), u16(2), u16(16);
            f.write("data", 4);
            u32(32000);
            const std::string zeros(32000, '\0');
            f.write(zeros.data(), 32000);
        }
        const AcousticModel model = featureModel(TrainerOptions{});
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        try {
            prepareUtterance("s", path, {"hello"}, model, lexicon);
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.file(), path);
            QVERIFY(std::string(e.what()).find("silent") != std::string::npos);
        }
    }
};

QTEST_GUILESS_MAIN(TestAligner)
#include "tst_aligner.moc"
