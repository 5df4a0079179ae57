#include "dynamics/LabelledSequence.h"

#include "util/Error.h"

#include <cmath>

namespace lipsync {

void validateLabels(const std::vector<int> &labels, const std::string &what, int states)
{
    if (labels.empty())
        throw Error("no frames", what);
    for (size_t t = 0; t < labels.size(); ++t)
        if (labels[t] < 0 || labels[t] >= states)
            throw Error("frame " + std::to_string(t) + ": label " + std::to_string(labels[t])
                            + " outside 0.." + std::to_string(states - 1),
                        what);
}

void checkStateLabel(int label, int states)
{
    if (label < 0 || label >= states)
        throw Error("label " + std::to_string(label) + " outside 0.." + std::to_string(states - 1));
}

void validateSequences(const std::vector<LabelledSequence> &sequences, int states)
{
    if (sequences.empty())
        throw Error("no training sequences");
    const Eigen::Index d = sequences.front().features.cols();
    for (size_t s = 0; s < sequences.size(); ++s) {
        const LabelledSequence &seq = sequences[s];
        const std::string name = seq.name.empty() ? "sequence " + std::to_string(s) : seq.name;
        if (seq.features.cols() == 0)
            throw Error("no feature dimensions", name);
        if (seq.features.cols() != d)
            throw Error("has " + std::to_string(seq.features.cols()) + " feature dimensions, "
                            + "expected " + std::to_string(d) + " like the first sequence",
                        name);
        if (seq.labels.empty())
            throw Error("no frames", name);
        if (Eigen::Index(seq.labels.size()) != seq.features.rows())
            throw Error(std::to_string(seq.labels.size()) + " frame labels but "
                            + std::to_string(seq.features.rows()) + " feature rows",
                        name);
        validateLabels(seq.labels, name, states);
        for (Eigen::Index t = 0; t < seq.features.rows(); ++t)
            for (Eigen::Index k = 0; k < d; ++k)
                if (!std::isfinite(seq.features(t, k)))
                    throw Error("feature " + std::to_string(k) + " of frame " + std::to_string(t)
                                    + " is not finite",
                                name);
    }
}

FrameStatistics computeFrameStatistics(const std::vector<LabelledSequence> &sequences, int states)
{
    const int P = states;
    const Eigen::Index d = sequences.front().features.cols();
    FrameStatistics st;
    st.mean = Eigen::MatrixXd::Zero(P, d);
    st.variance = Eigen::MatrixXd::Zero(P, d);
    st.count = Eigen::VectorXi::Zero(P);
    st.startCount = Eigen::VectorXi::Zero(P);
    st.transitionCount = Eigen::VectorXi::Zero(P);
    st.globalMean = Eigen::VectorXd::Zero(d);
    st.globalVariance = Eigen::VectorXd::Zero(d);
    for (const LabelledSequence &seq : sequences) {
        st.startCount[seq.labels[0]]++;
        for (size_t t = 0; t < seq.labels.size(); ++t) {
            const int n = seq.labels[t];
            st.count[n]++;
            if (t > 0)
                st.transitionCount[n]++;
            st.mean.row(n) += seq.features.row(Eigen::Index(t));
            st.globalMean += seq.features.row(Eigen::Index(t)).transpose();
        }
        st.frames += seq.frameCount();
    }
    st.globalMean /= double(st.frames);
    for (int n = 0; n < P; ++n)
        if (st.count[n] > 0)
            st.mean.row(n) /= double(st.count[n]);
    // Second pass for numerically stable variances.
    for (const LabelledSequence &seq : sequences)
        for (size_t t = 0; t < seq.labels.size(); ++t) {
            const int n = seq.labels[t];
            const Eigen::RowVectorXd y = seq.features.row(Eigen::Index(t));
            st.variance.row(n) += (y - st.mean.row(n)).array().square().matrix();
            st.globalVariance += (y.transpose() - st.globalMean).array().square().matrix();
        }
    st.globalVariance /= double(st.frames);
    st.floor = (1e-6 * st.globalVariance).cwiseMax(1e-12);
    st.globalVariance = st.globalVariance.cwiseMax(st.floor);
    for (int n = 0; n < P; ++n) {
        if (st.count[n] >= kMinimumVarianceFrames) {
            st.variance.row(n) /= double(st.count[n]);
            st.variance.row(n) = st.variance.row(n).cwiseMax(st.floor.transpose());
        } else if (st.count[n] > 0) {
            // A rare phone (§0): its own mean, the global variance.
            st.variance.row(n) = st.globalVariance.transpose();
        } else {
            // Unseen state (§1 [choice]): global mean and variance.
            st.mean.row(n) = st.globalMean.transpose();
            st.variance.row(n) = st.globalVariance.transpose();
        }
    }
    return st;
}

} // namespace lipsync
