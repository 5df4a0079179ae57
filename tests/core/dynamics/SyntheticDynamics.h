#pragma once
// Synthetic labelled data for the dynamics tests: phone sequences made of runs (like aligned
// speech: a few frames per phone, starting in silence) and features sampled from a DPDS; the
// message of a bad-input error.
#include "dynamics/LabelledSequence.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <Eigen/Core>

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace lipsync::test {

// What f throws as lipsync::Error, or empty if it throws nothing.
inline std::string errorOf(const std::function<void()> &f)
{
    try {
        f();
    } catch (const Error &e) {
        return e.what();
    }
    return {};
}

// Labels drawn from `states` in runs of 2..maxRun frames; the first run is silence when
// startInSilence.
inline std::vector<int> randomLabels(std::mt19937 &rng, int frames, const std::vector<int> &states,
                                     int maxRun = 6, bool startInSilence = true)
{
    std::uniform_int_distribution<size_t> pick(0, states.size() - 1);
    std::uniform_int_distribution<int> run(2, maxRun);
    std::vector<int> labels;
    int current = startInSilence ? PhoneSet::kSilence : states[pick(rng)];
    while (int(labels.size()) < frames) {
        const int length = run(rng);
        for (int i = 0; i < length && int(labels.size()) < frames; ++i)
            labels.push_back(current);
        current = states[pick(rng)];
    }
    return labels;
}

struct DpdsTruth
{
    Eigen::MatrixXd a, mu, nu; // P x d
    Eigen::VectorXd r;         // d
    double sigma = 0.1;        // t = 1 noise s.d.
};

inline DpdsTruth randomDpdsTruth(std::mt19937 &rng, int d, double noise)
{
    const int P = PhoneSet::kCount;
    std::uniform_real_distribution<double> aDist(0.2, 0.9), mDist(-2.0, 2.0);
    DpdsTruth truth;
    truth.a.resize(P, d);
    truth.mu.resize(P, d);
    truth.nu.resize(P, d);
    for (int n = 0; n < P; ++n)
        for (int k = 0; k < d; ++k) {
            truth.a(n, k) = aDist(rng);
            const double target = mDist(rng);
            truth.nu(n, k) = (1.0 - truth.a(n, k)) * target;
            truth.mu(n, k) = target;
        }
    truth.r = Eigen::VectorXd::Constant(d, noise * noise);
    truth.sigma = noise;
    return truth;
}

inline LabelledSequence sampleDpds(std::mt19937 &rng, const DpdsTruth &truth,
                                   const std::vector<int> &labels, const std::string &name)
{
    const Eigen::Index d = truth.a.cols();
    std::normal_distribution<double> normal;
    LabelledSequence s;
    s.name = name;
    s.labels = labels;
    s.features.resize(Eigen::Index(labels.size()), d);
    Eigen::VectorXd x = truth.mu.row(labels[0]).transpose();
    for (size_t t = 0; t < labels.size(); ++t) {
        const int n = labels[t];
        if (t > 0)
            x = truth.a.row(n).transpose().cwiseProduct(x) + truth.nu.row(n).transpose();
        for (Eigen::Index k = 0; k < d; ++k) {
            const double sd = t == 0 ? truth.sigma : std::sqrt(truth.r[k]);
            s.features(Eigen::Index(t), k) = x[k] + sd * normal(rng);
        }
    }
    return s;
}

inline std::vector<LabelledSequence> dpdsDataset(std::mt19937 &rng, const DpdsTruth &truth,
                                                 const std::vector<int> &states, int sequences,
                                                 int frames)
{
    std::vector<LabelledSequence> data;
    for (int s = 0; s < sequences; ++s)
        data.push_back(sampleDpds(rng, truth, randomLabels(rng, frames, states),
                                  "seq" + std::to_string(s)));
    return data;
}

inline double relativeError(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
{
    return (a - b).norm() / std::max(1e-300, std::max(a.norm(), b.norm()));
}

} // namespace lipsync::test
