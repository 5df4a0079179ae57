// Dynamics benchmarks (targets: docs/performance.md):
//  - DPDS: VarPro/LM vs the paper's gradient ascent, time to the same log-likelihood;
//  - DPDS training on ~20 min of GRID-like data (30000 frames, d = 32);
//  - DPDS streaming generation, frames/s (d = 32);
//  - Brand: tridiagonal vs block (dense d x d blocks) MLPG solve, 60 s at 25 fps, d = 32;
//  - the whole 10-fold evaluation of the four models.
// Labels are real GRID s1 sentences: word timings from the GRID .align files
// (../shared/data/grid-s1/align, else the 10 demo clips repeated), each word's span split evenly
// over its CMU-dictionary phones, voted to 25 fps frames (docs/models.md §0). Features are sampled
// from a random DPDS (a in [0.2, 0.9], noise s.d. 0.05) of any dimension d.
#include "dynamics/BrandModel.h"
#include "dynamics/DpdsModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "dynamics/SldsModel.h"
#include "eval/Evaluation.h"
#include "io/GridAlign.h"
#include "tasks/Feedback.h"
#include "util/PhoneSet.h"

#include <benchmark/benchmark.h>

#include <QDir>

#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

using namespace lipsync;

namespace {

std::map<std::string, std::vector<std::string>> cmuDictionary()
{
    std::map<std::string, std::vector<std::string>> dict;
    std::ifstream in("/usr/share/pocketsphinx/model/en-us/cmudict-en-us.dict");
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string word, phone;
        fields >> word;
        if (word.empty() || word.find('(') != std::string::npos)
            continue;
        std::vector<std::string> phones;
        while (fields >> phone)
            phones.push_back(phone);
        dict[word] = phones;
    }
    return dict;
}

// Per-clip frame labels of GRID s1 (75 frames each).
const std::vector<std::vector<int>> &gridLabels()
{
    static const std::vector<std::vector<int>> labels = [] {
        std::vector<std::vector<int>> out;
        const auto dict = cmuDictionary();
        QDir dir(QStringLiteral("/work/shared/data/grid-s1/align"));
        if (!dir.exists())
            dir = QDir(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media"));
        const QStringList files = dir.entryList({QStringLiteral("*.align")}, QDir::Files, QDir::Name);
        for (const QString &file : files) {
            const Tier words = readGridAlign(dir.filePath(file).toStdString());
            Tier phones{"phones", {}};
            for (const Interval &w : words.intervals) {
                const auto it = dict.find(w.label);
                if (w.label == "sil" || w.label == "sp" || it == dict.end()) {
                    phones.intervals.push_back({w.start, w.end, "sil"});
                    continue;
                }
                const double step = (w.end - w.start) / double(it->second.size());
                for (size_t i = 0; i < it->second.size(); ++i)
                    phones.intervals.push_back({w.start + step * double(i), w.start + step * double(i + 1), it->second[i]});
            }
            out.push_back(frameLabelsFromTier(phones, 25.0, 75));
        }
        // The demo fallback holds 10 clips: repeat to 400.
        const size_t real = out.size();
        for (size_t i = 0; real > 0 && out.size() < 400; ++i)
            out.push_back(out[i % real]);
        return out;
    }();
    return labels;
}

std::vector<LabelledSequence> gridLikeData(int d, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    const int P = PhoneSet::kCount;
    std::uniform_real_distribution<double> aDist(0.2, 0.9), mDist(-2.0, 2.0);
    std::normal_distribution<double> noise(0.0, 0.05);
    Eigen::MatrixXd a(P, d), nu(P, d), mu(P, d);
    for (int n = 0; n < P; ++n)
        for (int k = 0; k < d; ++k) {
            a(n, k) = aDist(rng);
            mu(n, k) = mDist(rng);
            nu(n, k) = (1 - a(n, k)) * mu(n, k);
        }
    std::vector<LabelledSequence> data;
    for (const std::vector<int> &labels : gridLabels()) {
        LabelledSequence s;
        s.name = "grid" + std::to_string(data.size());
        s.labels = labels;
        s.features.resize(Eigen::Index(labels.size()), d);
        Eigen::VectorXd x = mu.row(labels[0]).transpose();
        for (size_t t = 0; t < labels.size(); ++t) {
            if (t > 0)
                x = a.row(labels[t]).transpose().cwiseProduct(x) + nu.row(labels[t]).transpose();
            for (int k = 0; k < d; ++k)
                s.features(Eigen::Index(t), k) = x[k] + noise(rng);
        }
        data.push_back(std::move(s));
    }
    return data;
}

// Process CPU seconds (all threads): on a shared, oversubscribed machine wall time overstates the
// cost; CPU time does not.
double cpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double loglikPerFrame(const DynamicModel &m, const std::vector<LabelledSequence> &data)
{
    double ll = 0, frames = 0;
    for (const auto &s : data) {
        ll += m.logLikelihood(s.labels, s.features);
        frames += s.frameCount();
    }
    return ll / frames;
}

// LM to convergence, then gradient ascent until its objective per frame is within 1e-3 of LM's
// (or its iteration budget runs out). Reports both times and their ratio.
void BM_DpdsLmVersusGradientAscent(benchmark::State &state)
{
    const int d = int(state.range(0));
    const auto data = gridLikeData(d);
    double frames = 0;
    for (const auto &s : data)
        frames += s.frameCount();
    for (auto _ : state) {
        // Both start from a = 0.5 (docs/models.md §7.7), not from the AR(1) fit, which on data
        // sampled from a DPDS is already close to the optimum.
        DpdsOptions lmOptions;
        lmOptions.autoregressiveInit = false;
        DpdsModel lm(lmOptions);
        Feedback lmFeedback;
        double lmObjective = 0;
        lmFeedback.onIteration = [&](int, double objective) { lmObjective = objective; };
        auto start = std::chrono::steady_clock::now();
        double cpu = cpuSeconds();
        lm.train(data, lmFeedback);
        const double lmSeconds = seconds(start);
        const double lmCpu = cpuSeconds() - cpu;

        DpdsOptions options;
        options.optimizer = DpdsOptions::Optimizer::GradientAscent;
        options.autoregressiveInit = false;
        options.maxIterations = int(state.range(1));
        options.tolerance = 0;
        DpdsModel ga(options);
        Feedback gaFeedback;
        double gaSeconds = 0, gaObjective = -INFINITY;
        int gaIterations = 0;
        double gaCpu = 0;
        start = std::chrono::steady_clock::now();
        cpu = cpuSeconds();
        gaFeedback.onIteration = [&](int i, double objective) {
            gaObjective = objective;
            gaIterations = i;
            if (objective >= lmObjective - 1e-3 * frames && gaSeconds == 0) {
                gaSeconds = seconds(start);
                gaCpu = cpuSeconds() - cpu;
                gaFeedback.cancel();
            }
        };
        try {
            ga.train(data, gaFeedback);
        } catch (const Canceled &) {
        }
        const bool reached = gaSeconds > 0;
        if (!reached) {
            gaSeconds = seconds(start);
            gaCpu = cpuSeconds() - cpu;
        }
        state.counters["lm_cpu_s"] = lmCpu;
        state.counters["ga_cpu_s"] = gaCpu;
        state.counters["speedup_cpu"] = gaCpu / lmCpu;
        state.counters["lm_s"] = lmSeconds;
        state.counters["lm_iterations"] = lm.iterations();
        state.counters["lm_objective_per_frame"] = lmObjective / frames;
        state.counters["ga_s"] = gaSeconds;
        state.counters["ga_iterations"] = gaIterations;
        state.counters["ga_objective_per_frame"] = gaObjective / frames;
        state.counters["ga_reached_lm_within_1e-3"] = reached;
        state.counters["speedup"] = gaSeconds / lmSeconds;
    }
}
BENCHMARK(BM_DpdsLmVersusGradientAscent)->Args({1, 20000})->Args({8, 3000})->Iterations(1)->Unit(benchmark::kSecond);

void BM_DpdsTrain20Minutes(benchmark::State &state)
{
    const auto data = gridLikeData(32);
    double frames = 0;
    for (const auto &s : data)
        frames += s.frameCount();
    for (auto _ : state) {
        DpdsOptions options;
        options.threads = int(state.range(0));
        DpdsModel model(options);
        Feedback feedback;
        const auto start = std::chrono::steady_clock::now();
        const double cpu = cpuSeconds();
        model.train(data, feedback);
        state.counters["train_s"] = seconds(start);
        state.counters["train_cpu_s"] = cpuSeconds() - cpu;
        state.counters["frames"] = frames;
        state.counters["iterations"] = model.iterations();
        state.counters["loglik_per_frame"] = loglikPerFrame(model, data);
    }
}
BENCHMARK(BM_DpdsTrain20Minutes)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

void BM_DpdsStreaming(benchmark::State &state)
{
    const auto data = gridLikeData(32);
    std::vector<LabelledSequence> few(data.begin(), data.begin() + 40);
    DpdsModel model;
    Feedback feedback;
    model.train(few, feedback);
    std::vector<int> labels;
    for (const auto &l : gridLabels())
        labels.insert(labels.end(), l.begin(), l.end());
    auto stream = model.streamer();
    Eigen::VectorXd frame(32);
    double checksum = 0;
    for (auto _ : state) {
        for (int label : labels) {
            stream->push(label);
            stream->pop(frame);
        }
        checksum += frame[0];
    }
    benchmark::DoNotOptimize(checksum);
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(labels.size()));
}
BENCHMARK(BM_DpdsStreaming)->Unit(benchmark::kMillisecond);

// 60 s at 25 fps, d = 32: a GRID-like label sequence of 1500 frames.
std::vector<int> sixtySeconds()
{
    std::vector<int> labels;
    for (const auto &l : gridLabels()) {
        labels.insert(labels.end(), l.begin(), l.end());
        if (labels.size() >= 1500)
            break;
    }
    labels.resize(1500);
    return labels;
}

const BrandModel &brandModel()
{
    static const BrandModel model = [] {
        BrandModel m;
        Feedback feedback;
        m.train(gridLikeData(32), feedback);
        return m;
    }();
    return model;
}

void BM_BrandTridiagonal(benchmark::State &state)
{
    const auto labels = sixtySeconds();
    const BrandModel &model = brandModel();
    for (auto _ : state)
        benchmark::DoNotOptimize(model.generate(labels));
    state.SetItemsProcessed(int64_t(state.iterations()) * 1500);
}
BENCHMARK(BM_BrandTridiagonal)->Unit(benchmark::kMillisecond);

void BM_BrandBlockDense(benchmark::State &state)
{
    const auto labels = sixtySeconds();
    const BrandModel &model = brandModel();
    Eigen::MatrixXd block;
    for (auto _ : state)
        benchmark::DoNotOptimize(block = model.generateBlock(labels));
    state.counters["max_difference"] = (block - model.generate(labels)).cwiseAbs().maxCoeff();
    state.SetItemsProcessed(int64_t(state.iterations()) * 1500);
}
BENCHMARK(BM_BrandBlockDense)->Unit(benchmark::kMillisecond);

void BM_Evaluate10Fold(benchmark::State &state)
{
    const auto data = gridLikeData(32);
    for (auto _ : state) {
        EvaluationOptions options;
        Feedback feedback;
        const auto start = std::chrono::steady_clock::now();
        const double cpu = cpuSeconds();
        const EvaluationResult r = evaluateModels(data, options, feedback);
        state.counters["evaluate_s"] = seconds(start);
        state.counters["evaluate_cpu_s"] = cpuSeconds() - cpu;
        for (const ModelEvaluation &m : r.models) {
            double total = 0;
            for (double s : m.trainingSeconds)
                total += s;
            state.counters[m.kind + "_train_s"] = total;
            state.counters[m.kind + "_rms"] = m.metrics.at("rms").mean;
            state.counters[m.kind + "_loglik"] = m.metrics.at("loglik").mean;
        }
    }
}
BENCHMARK(BM_Evaluate10Fold)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

namespace {
void BM_SldsTrain20Minutes(benchmark::State &state)
{
    const auto data = gridLikeData(32);
    for (auto _ : state) {
        SldsModel model;
        Feedback feedback;
        const auto start = std::chrono::steady_clock::now();
        const double cpu = cpuSeconds();
        model.train(data, feedback);
        state.counters["train_s"] = seconds(start);
        state.counters["train_cpu_s"] = cpuSeconds() - cpu;
        state.counters["em_iterations"] = double(model.objectiveHistory().size());
        state.counters["loglik_per_frame"] = loglikPerFrame(model, data);
    }
}
BENCHMARK(BM_SldsTrain20Minutes)->Iterations(1)->Unit(benchmark::kSecond);
} // namespace

namespace {
// Training and generation of each of the four models (docs/models.md) through the model factory, on
// the same data: 40 GRID-like sentences (3000 frames = 2 min at 25 fps), d = 32. Generation is 60 s
// of speech (1500 frames); real-time factor = generation time / 60 s.
std::vector<LabelledSequence> twoMinutes()
{
    auto data = gridLikeData(32);
    data.resize(40);
    return data;
}

void BM_ModelTrain(benchmark::State &state, const std::string &kind)
{
    const auto data = twoMinutes();
    for (auto _ : state) {
        auto model = createDynamicModel(kind);
        Feedback feedback;
        const double cpu = cpuSeconds();
        model->train(data, feedback);
        state.counters["train_cpu_s"] = cpuSeconds() - cpu;
    }
    state.counters["frames"] = 3000;
}
BENCHMARK_CAPTURE(BM_ModelTrain, hmm, std::string("hmm"))->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelTrain, brand, std::string("brand"))->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelTrain, slds, std::string("slds"))->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelTrain, dpds, std::string("dpds"))->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_ModelGenerate(benchmark::State &state, const std::string &kind)
{
    auto model = createDynamicModel(kind);
    Feedback feedback;
    model->train(twoMinutes(), feedback);
    const auto labels = sixtySeconds();
    for (auto _ : state)
        benchmark::DoNotOptimize(model->generate(labels));
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(labels.size()));
    state.counters["media_s"] = double(labels.size()) / 25.0;
}
BENCHMARK_CAPTURE(BM_ModelGenerate, hmm, std::string("hmm"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelGenerate, brand, std::string("brand"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelGenerate, slds, std::string("slds"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ModelGenerate, dpds, std::string("dpds"))->Unit(benchmark::kMillisecond);
} // namespace

