#pragma once
// The Gaussian codebooks of a CMU Sphinx phonetically-tied-mixture (PTM) acoustic model, such as
// Debian's pocketsphinx-en-us: per CI phone and feature stream, `densities()` diagonal Gaussians
// (files means, variances) shared by all of that phone's senones, each senone with its own
// mixture weights (file sendump: 8-bit quantised -log weights). pocketsphinx keeps these private;
// SphinxAdaptation needs them to estimate a speaker's MLLR transform.
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace lipsync {

class SphinxCodebooks
{
public:
    using Matrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

    // Reads `modelDir`/means, variances (Sphinx-3 parameter files) and
    // sendump. `logBase` is the decoder's -logbase (the unit of the quantised weights),
    // `varianceFloor` its -varfloor. lipsync::Error naming the file for anything unreadable or
    // inconsistent (shapes that differ between the files, `senones` weights per codeword).
    static SphinxCodebooks read(const std::string &modelDir, int senones, double logBase = 1.0001,
                                double varianceFloor = 1e-4);

    // The two file formats, parsed from a file's bytes (`fileName` for errors; fuzz targets
    // sphinxgauden and sphinxsendump).
    struct Gaussians
    {
        int codebooks = 0, streams = 0, densities = 0;
        std::vector<int> lengths;  // per stream
        std::vector<float> values; // codebook x stream x density x length
    };
    static Gaussians parseGaussians(const std::string &bytes, const std::string &fileName);
    // stream x density x senone quantised weights; the file's shape must be the one given.
    static std::vector<uint8_t> parseMixtureWeights(const std::string &bytes, const std::string &fileName,
                                                    int streams, int densities, int senones);

    int codebooks() const { return m_codebooks; }
    int streams() const { return int(m_streamLength.size()); }
    int densities() const { return m_densities; }
    int senones() const { return m_senones; }
    int streamLength(int stream) const { return m_streamLength.at(size_t(stream)); }
    // densities() x streamLength(stream)
    const Matrix &means(int codebook, int stream) const { return m_means.at(index(codebook, stream)); }
    const Matrix &variances(int codebook, int stream) const { return m_variances.at(index(codebook, stream)); }
    // Natural log of senone `senone`'s weight of `density` in `stream`.
    double logWeight(int stream, int density, int senone) const
    {
        return -m_weightUnit * m_weights[(size_t(stream) * size_t(m_densities) + size_t(density)) * size_t(m_senones) + size_t(senone)];
    }

private:
    size_t index(int codebook, int stream) const { return size_t(codebook) * m_streamLength.size() + size_t(stream); }

    int m_codebooks = 0, m_densities = 0, m_senones = 0;
    std::vector<int> m_streamLength;
    std::vector<Matrix> m_means, m_variances;
    std::vector<uint8_t> m_weights; // stream x density x senone
    double m_weightUnit = 0;        // nats per quantisation step
};

} // namespace lipsync
