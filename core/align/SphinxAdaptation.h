#pragma once
// Speaker adaptation for SphinxAligner, as Kaldi / MFA and HTK do it ("align, adapt, re-align"):
// the first alignment's state path assigns each frame to a senone; within the senone's codebook
// every Gaussian takes its posterior share of the frame (mixture weight times likelihood); these
// statistics give one global MLLR mean transform per feature stream (Leggetter & Woodland 1995,
// MllrStatistics), mu' = A mu + b for every Gaussian of every codebook, which pocketsphinx
// applies to its model (ps_mllr_read's text format, acmod_update_mllr) before the second pass.
#include "align/MllrStatistics.h"
#include "align/SphinxCodebooks.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

class SphinxAdaptation
{
public:
    explicit SphinxAdaptation(const SphinxCodebooks &codebooks);

    // One frame's features (one pointer per stream, streamLength(f) values each) aligned to
    // `senone`, whose Gaussians are codebook `codebook`'s.
    void addFrame(const float *const *features, int senone, int codebook);
    double frames() const { return m_frames; }

    // Per stream, W (n x n+1): mu' = W (1, mu).
    std::vector<Eigen::MatrixXd> transforms() const;
    // The transforms in pocketsphinx's MLLR file format (one class; per stream its length, A,
    // b, and variance scales of 1).
    static std::string pocketsphinxText(const std::vector<Eigen::MatrixXd> &transforms);

private:
    size_t index(int codebook, int stream) const { return size_t(codebook) * size_t(m_codebooks.streams()) + size_t(stream); }

    const SphinxCodebooks &m_codebooks;
    // Per codebook and stream: each density's occupancy and occupancy-weighted sum of frames,
    // and -1/2 sum log var (the likelihood's normaliser without 2 pi, which cancels).
    std::vector<Eigen::VectorXd> m_occupancy, m_logNorm;
    std::vector<Eigen::MatrixXd> m_sum;
    double m_frames = 0;
};

} // namespace lipsync
