// Speech benchmarks and the aligner's accuracy evaluation (targets: docs/performance.md). They read
// ../shared/data when present and skip otherwise.
//   BM_Mfcc                 MFCC_0_D_A of 60 s of audio (real-time factor counter "rtf")
//   BM_MfccAndAlign/A       MFCC + Viterbi alignment of the 10 GRID demo clips (x8) with the
//                           shipped model on all cores, decoding excluded; "rtf" = wall seconds
//                           per second of audio; A = 1: with speaker adaptation (align --adapt);
//                           A = 2: SphinxAligner (CMU Sphinx en-us triphones, one scorer per thread);
//                           A = 3: SphinxAligner adapted to each clip (align --model sphinx --adapt)
//   BM_TrainGrid20min       training on all 400 GRID s1 clips (20 min of audio), features given
//   BM_EvalGridWords/A      train on 320 GRID s1 clips, align the other 80: share of word
//                           boundaries within 40 ms of GRID's .align ("inner": without the
//                           boundaries between the leading/trailing silence and the first/last word);
//                           A = 1: each clip aligned after speaker adaptation to itself. The 80 are
//                           the last by name, all "set ..." sentences: a split by name, kept as the
//                           historical row
//   BM_EvalGridWordsKFold   the same measure by 5-fold cross-validation over a random split of the
//                           400 clips (seed 2007, eval/CrossValidation): every clip aligned once by a
//                           model trained on the 320 of the other folds
//   BM_LivePhonesKFold      live phone recognition (StreamingPhoneRecognizer) by the same 5 folds:
//                           phone error rate and frames with the forced alignment's phone
//   BM_EvalMfaPhones/N      phone boundaries within 25 ms of the Montreal Forced Aligner's on
//                           ../shared/data/speech/mfa-tests (the 3 files with an ARPAbet phone
//                           tier), for words whose phones agree with MFA's; N = 0: model trained on
//                           those recordings, 1: on them plus GRID s1, 2: the shipped GRID s1 model,
//                           3: the shipped model adapted to each recording (SpeakerAdaptation),
//                           4: adapted to the three recordings together (one speaker; aligner adapt),
//                           5: SphinxAligner (CMU Sphinx's generic en-us model, align --model sphinx),
//                           6: SphinxAligner adapted to each recording (align --model sphinx --adapt)
// LIPSYNC_SPHINX_ARGS="-name value ..." adds pocketsphinx options to SphinxAligner's (tuning).
// LIPSYNC_BENCH_NORMALIZE=none|mean|cmvn chooses the per-utterance feature normalisation of the
// models trained here (default: TrainerOptions' own).
#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
#include "align/FrameLabels.h"
#include "align/PhoneBigram.h"
#include "align/PhoneErrorRate.h"
#include "align/StreamingPhoneRecognizer.h"
#include "align/SpeakerAdaptation.h"
#include "align/SphinxAligner.h"
#include "eval/CrossValidation.h"
#include "util/PhoneSet.h"
#include "io/AudioDecoder.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <mutex>
#include <numeric>

using namespace lipsync;

namespace {

const std::string kShared = LIPSYNC_SOURCE_DIR "/../shared/data";
const std::string kGrid = kShared + "/grid-s1";
const std::string kMfa = kShared + "/speech/mfa-tests";
const std::string kModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";

bool exists(const std::string &p)
{
    return std::filesystem::exists(p);
}

// SphinxAligner with the options of $LIPSYNC_SPHINX_ARGS; null (and the benchmark skipped) when
// the model is not installed.
std::unique_ptr<SphinxAligner> sphinxAligner(benchmark::State &state, bool adapt)
{
    if (!SphinxAligner::available()) {
        state.SkipWithError("CMU Sphinx en-us model (pocketsphinx-en-us) not installed");
        return nullptr;
    }
    SphinxAligner::Options o;
    const QStringList args = qEnvironmentVariable("LIPSYNC_SPHINX_ARGS").split(' ', Qt::SkipEmptyParts);
    for (qsizetype i = 0; i + 1 < args.size(); i += 2)
        o.extraArguments.emplace_back(args[i].toStdString(), args[i + 1].toStdString());
    // LIPSYNC_SPHINX_ADAPT=N: N adaptation passes instead of one (tuning).
    o.adaptationPasses = adapt ? (qEnvironmentVariableIsSet("LIPSYNC_SPHINX_ADAPT") ? qEnvironmentVariableIntValue("LIPSYNC_SPHINX_ADAPT") : 1) : 0;
    return std::make_unique<SphinxAligner>(o);
}

TrainerOptions benchOptions()
{
    TrainerOptions o; // the defaults: up to 16 mixtures, 8 + 4 x 6 iterations
    const std::string normalize = qEnvironmentVariable("LIPSYNC_BENCH_NORMALIZE").toStdString();
    if (normalize == "none")
        o.normalization = CepstralNormalization::None;
    else if (normalize == "mean")
        o.normalization = CepstralNormalization::Mean;
    else if (normalize == "cmvn")
        o.normalization = CepstralNormalization::MeanAndVariance;
    return o;
}

const Lexicon &lexicon()
{
    static const Lexicon l(&PronunciationDictionary::cmu());
    return l;
}

struct GridClip
{
    PreparedUtterance utterance;
    Tier reference;
};

// All 400 GRID s1 clips, decoded once per process (sorted by name: the first 320 train).
const std::vector<GridClip> &gridClips()
{
    static const std::vector<GridClip> clips = [] {
        std::vector<std::string> ids;
        for (const auto &e : std::filesystem::directory_iterator(kGrid + "/video"))
            ids.push_back(e.path().stem().string());
        std::sort(ids.begin(), ids.end());
        const AcousticModel features = featureModel(benchOptions());
        std::vector<GridClip> out(ids.size());
        std::vector<int> index(ids.size());
        std::iota(index.begin(), index.end(), 0);
        QtConcurrent::blockingMap(index, [&](int i) {
            const Transcript t = readTranscript(kGrid + "/align/" + ids[size_t(i)] + ".align");
            out[size_t(i)].utterance = prepareUtterance(ids[size_t(i)], kGrid + "/video/" + ids[size_t(i)] + ".mpg",
                                                        t.words, features, lexicon());
            out[size_t(i)].reference = t.timing;
        });
        return out;
    }();
    return clips;
}

TrainingUtterance trainingUtterance(const GridClip &clip)
{
    return {clip.utterance.id, clip.utterance.features, clip.utterance.pronunciations, clip.reference};
}

std::vector<TrainingUtterance> trainingSet(const std::vector<GridClip> &clips, size_t from, size_t to)
{
    std::vector<TrainingUtterance> out;
    for (size_t i = from; i < to && i < clips.size(); ++i)
        out.push_back(trainingUtterance(clips[i]));
    return out;
}

bool isSilence(const std::string &label)
{
    return label.empty() || label == "sil" || label == "sp" || label == "spn" || label == "<sil>";
}

std::vector<Interval> nonSilence(const Tier &tier)
{
    std::vector<Interval> out;
    for (const Interval &i : tier.intervals)
        if (!isSilence(i.label))
            out.push_back(i);
    return out;
}

// Alignment with `model`, or with `model` adapted to the utterance first (align --adapt).
AlignmentResult alignUtterance(const AcousticModel &model, const Eigen::MatrixXf &features,
                               const std::vector<std::string> &words,
                               const std::vector<std::vector<Pronunciation>> &pronunciations, double duration, bool adapt)
{
    std::optional<AcousticModel> adapted;
    if (adapt)
        adapted = SpeakerAdaptation::adapt(model, pronunciations, features);
    const AcousticModel &used = adapted ? *adapted : model;
    AlignmentResult r = ForcedAligner(used).align(features, words, pronunciations, duration);
    used.boundaryCorrection().apply(r); // as MonophoneAligner does: none once adapted
    return r;
}

void BM_Mfcc(benchmark::State &state)
{
    std::vector<float> samples(16000 * 60);
    for (size_t i = 0; i < samples.size(); ++i)
        samples[i] = float(0.3 * std::sin(0.05 * double(i)) + 0.01 * std::sin(1.3 * double(i)));
    const Mfcc mfcc;
    for (auto _ : state)
        benchmark::DoNotOptimize(mfcc.compute(samples));
    state.counters["rtf"] = benchmark::Counter(state.iterations() * 60.0, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Mfcc)->Unit(benchmark::kMillisecond);

// Wall-clock time of MFCC + alignment of the demo clips, both cores busy (QtConcurrent).
// Counter "rtf" = wall seconds per second of audio (target <= 0.02).
void BM_MfccAndAlign(benchmark::State &state)
{
    const bool sphinx = state.range(0) >= 2;
    const std::unique_ptr<SphinxAligner> sphinxModel = sphinx ? sphinxAligner(state, state.range(0) == 3) : nullptr;
    if (sphinx && !sphinxModel)
        return;
    if (!exists(kModel)) {
        state.SkipWithError("no shipped model");
        return;
    }
    const AcousticModel model = AcousticModel::load(kModel);
    const QDir demo(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media"));
    struct Clip
    {
        std::vector<float> samples;
        double duration;
        std::vector<std::string> words;
        std::vector<std::vector<Pronunciation>> pronunciations;
    };
    std::vector<Clip> clips;
    for (const QString &name : demo.entryList({QStringLiteral("*.mpg")}, QDir::Files, QDir::Name)) {
        const AudioBuffer audio = AudioDecoder::decode(demo.filePath(name).toStdString(), 16000);
        const Transcript t = readTranscript(demo.filePath(QFileInfo(name).completeBaseName() + ".align").toStdString());
        clips.push_back({audio.samples, audio.duration(), t.words, lexicon().pronounceAll(t.words)});
    }
    // Eight copies of the set so that both cores stay busy.
    std::vector<int> work;
    for (int copy = 0; copy < 8; ++copy)
        for (size_t i = 0; i < clips.size(); ++i)
            work.push_back(int(i));
    double audioSeconds = 0;
    for (int i : work)
        audioSeconds += clips[size_t(i)].duration;
    if (sphinx) // the decoders (one per thread) are created once, outside the timing
        QtConcurrent::blockingMap(work, [&](int i) {
            const Clip &c = clips[size_t(i)];
            sphinxModel->align(c.samples, c.words, c.pronunciations, c.duration);
        });
    for (auto _ : state) {
        QtConcurrent::blockingMap(work, [&](int i) {
            const Clip &c = clips[size_t(i)];
            if (sphinx) {
                benchmark::DoNotOptimize(sphinxModel->align(c.samples, c.words, c.pronunciations, c.duration));
                return;
            }
            const Eigen::MatrixXf f = model.features(c.samples);
            benchmark::DoNotOptimize(alignUtterance(model, f, c.words, c.pronunciations, c.duration, state.range(0) == 1));
        });
    }
    state.counters["rtf"] = benchmark::Counter(state.iterations() * audioSeconds, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["audio_s"] = audioSeconds;
}
BENCHMARK(BM_MfccAndAlign)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TrainGrid20min(benchmark::State &state)
{
    if (!exists(kGrid)) {
        state.SkipWithError("../shared/data/grid-s1 not present");
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto &clips = gridClips();
    state.counters["decode_and_features_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::vector<TrainingUtterance> all = trainingSet(clips, 0, clips.size());
    double audio = 0;
    for (const TrainingUtterance &u : all)
        audio += u.features.rows() * 0.01;
    const std::clock_t cpu0 = std::clock();
    for (auto _ : state) {
        Feedback feedback;
        benchmark::DoNotOptimize(AlignerTrainer::train(all, benchOptions(), feedback));
    }
    // Process CPU seconds (all threads): on a machine shared with other jobs wall time overstates.
    state.counters["train_cpu_s"] = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    state.counters["audio_min"] = audio / 60.0;
}
BENCHMARK(BM_TrainGrid20min)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// Word boundaries within 40 ms of the reference, over all boundaries and over the inner ones
// (not between the leading/trailing silence and the first/last word).
struct BoundaryScore
{
    int within = 0, total = 0, innerWithin = 0, inner = 0, mismatched = 0;
    void add(const Tier &reference, const Tier &aligned)
    {
        const std::vector<Interval> ref = nonSilence(reference), hyp = nonSilence(aligned);
        if (ref.size() != hyp.size()) {
            ++mismatched;
            return;
        }
        for (size_t w = 0; w < ref.size(); ++w)
            for (int edge = 0; edge < 2; ++edge) {
                const double d = edge ? hyp[w].end - ref[w].end : hyp[w].start - ref[w].start;
                const bool ok = std::abs(d) <= 0.040 + 1e-6;
                within += ok;
                ++total;
                const bool silenceEdge = (w == 0 && edge == 0) || (w + 1 == ref.size() && edge == 1);
                if (!silenceEdge) {
                    innerWithin += ok;
                    ++inner;
                }
            }
    }
    double innerPercent() const { return 100.0 * innerWithin / std::max(inner, 1); }
    double allPercent() const { return 100.0 * within / std::max(total, 1); }
    void report(benchmark::State &state) const
    {
        state.counters["inner_within_40ms_pct"] = innerPercent();
        state.counters["all_within_40ms_pct"] = allPercent();
        state.counters["boundaries"] = inner;
        state.counters["mismatched"] = mismatched;
    }
};

void BM_EvalGridWords(benchmark::State &state)
{
    if (!exists(kGrid)) {
        state.SkipWithError("../shared/data/grid-s1 not present");
        return;
    }
    const auto &clips = gridClips();
    const std::vector<TrainingUtterance> train = trainingSet(clips, 0, 320);
    BoundaryScore score;
    for (auto _ : state) {
        Feedback feedback;
        const AcousticModel model = AlignerTrainer::train(train, benchOptions(), feedback);
        for (size_t k = 320; k < clips.size(); ++k) {
            const PreparedUtterance &u = clips[k].utterance;
            const AlignmentResult r = alignUtterance(model, u.features, u.words, u.pronunciations, u.duration, state.range(0) == 1);
            score.add(clips[k].reference, r.words);
        }
    }
    score.report(state);
    std::printf("GRID s1 (train 320, align 80%s): %.1f%% of %d inner word boundaries within 40 ms "
                "(%.1f%% of %d with the silence edges)\n", state.range(0) == 1 ? ", adapted" : "",
                score.innerPercent(), score.inner, score.allPercent(), score.total);
}
BENCHMARK(BM_EvalGridWords)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_EvalGridWordsKFold(benchmark::State &state)
{
    if (!exists(kGrid)) {
        state.SkipWithError("../shared/data/grid-s1 not present");
        return;
    }
    const auto &clips = gridClips();
    const std::vector<std::vector<int>> folds = makeFolds(int(clips.size()), 5);
    BoundaryScore score, uncorrected;
    std::vector<int> minimumCounts;
    double lowest = 100.0, highest = 0.0;
    for (auto _ : state) {
        for (size_t f = 0; f < folds.size(); ++f) {
            std::vector<TrainingUtterance> train;
            for (int i : trainingMembers(folds, f))
                train.push_back(trainingUtterance(clips[size_t(i)]));
            Feedback feedback;
            AcousticModel model = AlignerTrainer::train(train, benchOptions(), feedback);
            // The boundary correction learned on the same training part (aligner calibrate).
            BoundaryCorrectionReport calibration;
            model.setBoundaryCorrection(AlignerTrainer::calibrate(model, train, {}, &calibration));
            minimumCounts.push_back(calibration.minimumCount);
            BoundaryScore fold;
            for (int i : folds[f]) {
                const PreparedUtterance &u = clips[size_t(i)].utterance;
                AlignmentResult r = ForcedAligner(model).align(u.features, u.words, u.pronunciations, u.duration);
                uncorrected.add(clips[size_t(i)].reference, r.words);
                model.boundaryCorrection().apply(r);
                fold.add(clips[size_t(i)].reference, r.words);
                score.add(clips[size_t(i)].reference, r.words);
            }
            lowest = std::min(lowest, fold.allPercent());
            highest = std::max(highest, fold.allPercent());
        }
    }
    score.report(state);
    state.counters["fold_all_min_pct"] = lowest;
    state.counters["fold_all_max_pct"] = highest;
    state.counters["uncorrected_all_pct"] = uncorrected.allPercent();
    std::printf("GRID s1, 5-fold random split of 400 clips: %.1f%% of all %d word boundaries within 40 ms "
                "(folds %.1f-%.1f%%), %.1f%% of %d inner; without the boundary correction %.1f%% of all, "
                "%.1f%% of the inner; minimum counts chosen:",
                score.allPercent(), score.total, lowest, highest, score.innerPercent(), score.inner,
                uncorrected.allPercent(), uncorrected.innerPercent());
    for (int m : minimumCounts)
        std::printf(" %d", m);
    std::printf("\n");
}
BENCHMARK(BM_EvalGridWordsKFold)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// How much transcribed speech a speaker's own aligner needs: the folds above, each fold's model
// trained (and its boundary correction learned) on only the first N clips of its training part in
// a seeded random order, the held-out fold scored as above. The studio's Make the Speaker's Own
// Aligner trains rather than adapts from the amount of speech where this beats CMU Sphinx adapted
// to each clip (85.7 % of all boundaries on the same 400 clips).
void BM_GridAlignerLearningCurve(benchmark::State &state)
{
    if (!exists(kGrid)) {
        state.SkipWithError("../shared/data/grid-s1 not present");
        return;
    }
    const auto &clips = gridClips();
    const std::vector<std::vector<int>> folds = makeFolds(int(clips.size()), 5);
    const size_t n = size_t(state.range(0));
    BoundaryScore score;
    double speechSeconds = 0;
    for (auto _ : state) {
        for (size_t f = 0; f < folds.size(); ++f) {
            std::vector<int> pool = trainingMembers(folds, f);
            std::mt19937 random(2007 + unsigned(f));
            std::shuffle(pool.begin(), pool.end(), random);
            std::vector<TrainingUtterance> train;
            for (size_t k = 0; k < std::min(n, pool.size()); ++k) {
                train.push_back(trainingUtterance(clips[size_t(pool[k])]));
                for (const Interval &w : nonSilence(clips[size_t(pool[k])].reference))
                    speechSeconds += (w.end - w.start) / double(folds.size());
            }
            Feedback feedback;
            AcousticModel model = AlignerTrainer::train(train, benchOptions(), feedback);
            model.setBoundaryCorrection(AlignerTrainer::calibrate(model, train, {}));
            for (int i : folds[f]) {
                const PreparedUtterance &u = clips[size_t(i)].utterance;
                AlignmentResult r = ForcedAligner(model).align(u.features, u.words, u.pronunciations, u.duration);
                model.boundaryCorrection().apply(r);
                score.add(clips[size_t(i)].reference, r.words);
            }
        }
    }
    score.report(state);
    state.counters["speech_min"] = speechSeconds / 60.0;
    std::printf("GRID s1, own aligner from %zu clips (%.2f min of words): %.1f%% of all %d word boundaries within "
                "40 ms, %.1f%% of the inner, %d clips with other words\n",
                n, speechSeconds / 60.0, score.allPercent(), score.total, score.innerPercent(), score.mismatched);
}
BENCHMARK(BM_GridAlignerLearningCurve)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Arg(120)->Arg(160)->Arg(320)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// Live recognition (StreamingPhoneRecognizer) by 5-fold cross-validation over the same random
// split: each fold's aligner model is trained on the 320 clips of the other folds, its phone bigram
// counted from that model's forced alignments of them, and the held-out 80 clips' sound fed in
// 10 ms blocks. Against the held-out clips' forced alignments (same model, known words): phone
// error rate, and the share of 100 Hz frames and of 25 fps video frames (the §0 vote) with the
// aligned phone. LIPSYNC_LIVE_LAG, _LW, _INS, _MEAN, _PRIOR override the recogniser's options;
// LIPSYNC_LIVE_TRAINING=1 scores 80 of the training clips of fold 1 instead (to choose them on
// training data); LIPSYNC_LIVE_FOLDS=N runs only the first N folds.
void BM_LivePhonesKFold(benchmark::State &state)
{
    if (!exists(kGrid)) {
        state.SkipWithError("../shared/data/grid-s1 not present");
        return;
    }
    const auto &clips = gridClips();
    const std::vector<std::vector<int>> folds = makeFolds(int(clips.size()), 5);
    PhoneRecognizerOptions options;
    auto setting = [](const char *name, double fallback) {
        return qEnvironmentVariableIsSet(name) ? qEnvironmentVariable(name).toDouble() : fallback;
    };
    options.lagFrames = int(setting("LIPSYNC_LIVE_LAG", options.lagFrames));
    options.languageWeight = setting("LIPSYNC_LIVE_LW", options.languageWeight);
    options.phoneInsertion = setting("LIPSYNC_LIVE_INS", options.phoneInsertion);
    options.meanSeconds = setting("LIPSYNC_LIVE_MEAN", options.meanSeconds);
    options.priorFrames = setting("LIPSYNC_LIVE_PRIOR", options.priorFrames);
    const bool onTraining = qEnvironmentVariableIntValue("LIPSYNC_LIVE_TRAINING") == 1;
    const size_t foldCount = std::min(folds.size(), size_t(setting("LIPSYNC_LIVE_FOLDS", double(folds.size()))));
    double errors = 0, referencePhones = 0, frames = 0, framesRight = 0, video = 0, videoRight = 0;
    for (auto _ : state) {
        for (size_t f = 0; f < foldCount; ++f) {
            const std::vector<int> trainIds = trainingMembers(folds, f);
            std::vector<TrainingUtterance> train;
            for (int i : trainIds)
                train.push_back(trainingUtterance(clips[size_t(i)]));
            Feedback feedback;
            const AcousticModel model = AlignerTrainer::train(train, benchOptions(), feedback);
            std::vector<Tier> aligned(clips.size());
            for (size_t i = 0; i < clips.size(); ++i) {
                const PreparedUtterance &u = clips[i].utterance;
                aligned[i] = alignUtterance(model, u.features, u.words, u.pronunciations, u.duration, false).phones;
            }
            std::vector<Tier> trainingTiers;
            for (int i : trainIds)
                trainingTiers.push_back(aligned[size_t(i)]);
            const PhoneBigram bigram = PhoneBigram::fromTiers(trainingTiers);
            std::vector<int> scored = folds[f];
            if (onTraining)
                scored.assign(trainIds.begin(), trainIds.begin() + long(std::min<size_t>(80, trainIds.size())));
            std::mutex mutex;
            QtConcurrent::blockingMap(scored, [&](int i) {
                const std::vector<float> sound =
                    AudioDecoder::decode(kGrid + "/video/" + clips[size_t(i)].utterance.id + ".mpg", 16000).samples;
                StreamingPhoneRecognizer r(model, bigram, options);
                std::vector<int> decided;
                for (size_t at = 0; at < sound.size(); at += 160) {
                    r.push(sound.data() + at, std::min<size_t>(160, sound.size() - at));
                    for (int p : r.takeDecided())
                        decided.push_back(p);
                }
                r.finish();
                for (int p : r.takeDecided())
                    decided.push_back(p);
                Tier recognised{"phones", {}};
                const MfccOptions &o = model.featureOptions();
                StreamingPhoneRecognizer::appendToTier(recognised, 0, decided, o);
                const Tier &reference = aligned[size_t(i)];
                const std::vector<int> ref = spokenPhones(reference);
                const double per = phoneErrorRate(ref, spokenPhones(recognised));
                int right = 0;
                for (size_t j = 0; j < decided.size(); ++j) {
                    const int at = reference.indexAt(mfccFrameCentre(int(j), o));
                    const int phone = at < 0 ? int(PhoneSet::kSilence) : PhoneSet::index(reference.intervals[size_t(at)].label);
                    right += phone == decided[j];
                }
                const int videoFrames = int(std::lround(clips[size_t(i)].utterance.duration * 25));
                const std::vector<std::string> truth = voteFrameLabels(reference, lipsync::FrameClock::uniform(25.0, videoFrames), o);
                const std::vector<std::string> guess = voteFrameLabels(recognised, lipsync::FrameClock::uniform(25.0, videoFrames), o);
                int videoSame = 0;
                for (int k = 0; k < videoFrames; ++k)
                    videoSame += truth[size_t(k)] == guess[size_t(k)];
                std::lock_guard lock(mutex);
                errors += per * double(ref.size());
                referencePhones += double(ref.size());
                frames += double(decided.size());
                framesRight += right;
                video += videoFrames;
                videoRight += videoSame;
            });
        }
    }
    state.counters["phone_error_rate_pct"] = 100.0 * errors / referencePhones;
    state.counters["frames_right_pct"] = 100.0 * framesRight / frames;
    state.counters["video_frames_right_pct"] = 100.0 * videoRight / video;
    const AcousticModel shipped = AcousticModel::load(kModel);
    state.counters["latency_ms"] = 1000.0 * StreamingPhoneRecognizer(shipped, PhoneBigram(), options).latencySeconds();
}
BENCHMARK(BM_LivePhonesKFold)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

struct MfaFile
{
    std::string media;
    PreparedUtterance utterance;
    Tier words, phones;
};

// mfa-tests recordings with an ARPAbet phone tier and a words tier.
std::vector<MfaFile> mfaFiles()
{
    std::vector<MfaFile> out;
    const AcousticModel features = featureModel(benchOptions());
    for (const auto &e : std::filesystem::directory_iterator(kMfa)) {
        if (e.path().extension() != ".TextGrid")
            continue;
        const TextGrid grid = readTextGrid(e.path().string());
        const Tier *words = grid.tier("words");
        const Tier *phones = grid.tier("phones");
        if (!words || !phones)
            continue;
        bool arpabet = true;
        for (const Interval &i : phones->intervals)
            arpabet = arpabet && (isSilence(i.label) || PhoneSet::index(i.label) >= 0);
        if (!arpabet)
            continue;
        std::string media;
        for (const char *ext : {".wav", ".flac"})
            if (exists(kMfa + "/" + e.path().stem().string() + ext))
                media = kMfa + "/" + e.path().stem().string() + ext;
        std::vector<std::string> list;
        for (const Interval &i : nonSilence(*words))
            list.push_back(i.label);
        out.push_back({media, prepareUtterance(e.path().stem().string(), media, list, features, lexicon()), *words, *phones});
    }
    return out;
}

// Phone boundaries (each phone's start, and its end when silence follows) of the words whose
// phone sequence agrees with MFA's, within 25 ms.
void comparePhones(const MfaFile &file, const AlignmentResult &r, int &within, int &total, int &wordsCompared, int &wordsSkipped)
{
    const std::vector<Interval> refWords = nonSilence(file.words), hypWords = nonSilence(r.words);
    auto phonesIn = [](const Tier &phones, const Interval &word) {
        std::vector<Interval> out;
        for (const Interval &p : phones.intervals)
            if (!isSilence(p.label) && p.start >= word.start - 1e-6 && p.end <= word.end + 1e-6)
                out.push_back(p);
        return out;
    };
    for (size_t w = 0; w < refWords.size() && w < hypWords.size(); ++w) {
        const auto ref = phonesIn(file.phones, refWords[w]), hyp = phonesIn(r.phones, hypWords[w]);
        bool same = ref.size() == hyp.size() && !ref.empty();
        for (size_t i = 0; same && i < ref.size(); ++i)
            same = PhoneSet::index(ref[i].label) == PhoneSet::index(hyp[i].label);
        if (!same) {
            ++wordsSkipped;
            continue;
        }
        ++wordsCompared;
        for (size_t i = 0; i < ref.size(); ++i) {
            within += std::abs(hyp[i].start - ref[i].start) <= 0.025 + 1e-6;
            ++total;
        }
        bool silenceFollows = true;
        for (const Interval &p : file.phones.intervals)
            if (p.start <= ref.back().end + 1e-4 && p.end > ref.back().end + 1e-4)
                silenceFollows = isSilence(p.label);
        if (silenceFollows) {
            within += std::abs(hyp.back().end - ref.back().end) <= 0.025 + 1e-6;
            ++total;
        }
    }
}

void BM_EvalMfaPhones(benchmark::State &state)
{
    if (!exists(kMfa)) {
        state.SkipWithError("../shared/data/speech/mfa-tests not present");
        return;
    }
    const std::vector<MfaFile> files = mfaFiles();
    if (state.range(0) >= 5) {
        const std::unique_ptr<SphinxAligner> sphinx = sphinxAligner(state, state.range(0) == 6);
        if (!sphinx)
            return;
        int within = 0, total = 0, compared = 0, skipped = 0;
        double audioSeconds = 0, alignSeconds = 0;
        for (auto _ : state)
            for (const MfaFile &f : files) {
                const AudioBuffer audio = AudioDecoder::decode(f.media, SphinxAligner::kSampleRate);
                const auto start = std::chrono::steady_clock::now();
                const AlignmentResult r = sphinx->align(audio.samples, f.utterance.words, f.utterance.pronunciations,
                                                        audio.duration());
                alignSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                audioSeconds += audio.duration();
                comparePhones(f, r, within, total, compared, skipped);
            }
        state.counters["within_25ms_pct"] = 100.0 * within / std::max(total, 1);
        state.counters["boundaries"] = total;
        state.counters["words_compared"] = compared;
        state.counters["words_other_pronunciation"] = skipped;
        state.counters["rtf_one_thread"] = alignSeconds / std::max(audioSeconds, 1e-9);
        std::printf("mfa-tests (%zu files, SphinxAligner%s %s): %.1f%% of %d phone boundaries within 25 ms of MFA "
                    "(%d words compared, %d with another pronunciation)\n",
                    files.size(), state.range(0) == 6 ? " adapted" : "", qPrintable(qEnvironmentVariable("LIPSYNC_SPHINX_ARGS")),
                    100.0 * within / std::max(total, 1), total, compared, skipped);
        return;
    }
    std::vector<TrainingUtterance> own;
    for (const MfaFile &f : files)
        own.push_back({f.utterance.id, f.utterance.features, f.utterance.pronunciations});
    // 0: trained on the mfa-tests recordings; 1: on them plus GRID s1; 2: the shipped GRID model.
    const bool withGrid = state.range(0) == 1;
    const bool adapt = state.range(0) == 3;
    const bool speakerAdapt = state.range(0) == 4;
    const bool shipped = state.range(0) >= 2;
    std::vector<TrainingUtterance> train = own;
    if (withGrid && exists(kGrid)) {
        const auto grid = trainingSet(gridClips(), 0, 400);
        train.insert(train.end(), grid.begin(), grid.end());
    }
    int within = 0, total = 0, compared = 0, skipped = 0;
    for (auto _ : state) {
        Feedback feedback;
        AcousticModel model = shipped ? AcousticModel::load(kModel) : AlignerTrainer::train(train, benchOptions(), feedback);
        if (speakerAdapt)
            model = SpeakerAdaptation::adapt(model, own);
        for (const MfaFile &f : files) {
            const AlignmentResult r = alignUtterance(model, f.utterance.features, f.utterance.words,
                                                     f.utterance.pronunciations, f.utterance.duration, adapt);
            comparePhones(f, r, within, total, compared, skipped);
        }
    }
    state.counters["within_25ms_pct"] = 100.0 * within / std::max(total, 1);
    state.counters["boundaries"] = total;
    state.counters["words_compared"] = compared;
    state.counters["words_other_pronunciation"] = skipped;
    std::printf("mfa-tests (%zu files, %s): %.1f%% of %d phone boundaries within 25 ms of MFA "
                "(%d words compared, %d with another pronunciation)\n",
                files.size(), speakerAdapt ? "shipped GRID s1 model adapted to all three" : adapt ? "shipped GRID s1 model adapted to each" : shipped ? "shipped GRID s1 model" : withGrid ? "trained on them + GRID s1" : "trained on them", 100.0 * within / std::max(total, 1), total, compared, skipped);
}
BENCHMARK(BM_EvalMfaPhones)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Arg(4)->Arg(5)->Arg(6)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

} // namespace
