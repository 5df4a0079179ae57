#include "align/SphinxCodebooks.h"

#include "align/SphinxFileReader.h"
#include "util/Error.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace lipsync {

namespace {

std::string readBytes(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read the CMU Sphinx model file", path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

} // namespace

// A Sphinx-3 Gaussian parameter file (pocketsphinx's gauden_param_read): a text header from "s3"
// to "endhdr", the byte-order magic 0x11223344, then int32 codebooks, streams, densities, each
// stream's length, the value count and the values (float32); a checksum may follow. Read here,
// not through sphinxbase's bio_readhdr, which exits the process (E_FATAL) on a malformed header.
SphinxCodebooks::Gaussians SphinxCodebooks::parseGaussians(const std::string &bytes, const std::string &fileName)
{
    SphinxFileReader r(bytes, fileName, "Sphinx-3 Gaussian parameter file");
    if (r.line("header") != "s3")
        throw Error("not a Sphinx-3 parameter file (no s3 header)", fileName);
    for (;;) {
        std::string line = r.line("header");
        line.erase(0, line.find_first_not_of(" \t"));
        if (line.rfind("endhdr", 0) == 0)
            break;
    }
    const uint32_t magic = r.u32("byte-order magic");
    if (magic == 0x44332211u)
        r.setSwap(true);
    else if (magic != 0x11223344u)
        throw Error("not a Sphinx-3 parameter file (bad byte-order magic)", fileName);
    Gaussians g;
    g.codebooks = r.i32("codebooks");
    g.streams = r.i32("streams");
    g.densities = r.i32("densities");
    if (g.codebooks < 1 || g.codebooks > 65536 || g.streams < 1 || g.streams > 8 || g.densities < 1 || g.densities > 65536)
        throw Error("implausible Gaussian parameter shape", fileName);
    uint64_t total = 0;
    for (int f = 0; f < g.streams; ++f) {
        const int length = r.i32("stream length");
        if (length < 1 || length > 1024)
            throw Error("implausible feature stream length " + std::to_string(length), fileName);
        g.lengths.push_back(length);
        total += uint64_t(length);
    }
    total *= uint64_t(g.codebooks) * uint64_t(g.densities);
    if (uint64_t(r.u32("value count")) != total)
        throw Error("the Gaussian parameter count does not match the file's shape", fileName);
    r.need(total * 4, "values");
    g.values.resize(size_t(total));
    for (float &v : g.values) {
        v = r.f32("values");
        if (!std::isfinite(v))
            throw Error("non-finite Gaussian parameter", fileName);
    }
    return g;
}

// pocketsphinx's sendump (ptm_mgau.c read_sendump): int32-length-prefixed header strings (NUL
// included, but for the padding that aligns the data: "!!!" in en-us) ended by a zero length,
// the codeword and senone counts when the header names no cluster count, then per stream and
// codeword one byte per senone: -log_b(w) >> 10 in the decoder's log base b. Clustered (4-bit)
// dumps are refused.
std::vector<uint8_t> SphinxCodebooks::parseMixtureWeights(const std::string &bytes, const std::string &fileName,
                                                          int streams, int densities, int senones)
{
    SphinxFileReader r(bytes, fileName, "pocketsphinx sendump");
    int clusters = 0, featureCount = streams;
    for (bool first = true;; first = false) {
        const int32_t n = r.i32("header string length");
        if (n == 0 && !first)
            break;
        if (n < 1 || n > 999)
            throw Error("not a pocketsphinx sendump file (header string length " + std::to_string(n) + ")", fileName);
        r.need(uint64_t(n), "header string");
        const std::string line(bytes.data() + r.position(), size_t(n));
        r.skip(uint64_t(n), "header string");
        const std::string text = line.substr(0, line.find('\0'));
        if (text.rfind("cluster_count ", 0) == 0)
            clusters = std::atoi(text.c_str() + 14);
        if (text.rfind("feature_count ", 0) == 0)
            featureCount = std::atoi(text.c_str() + 14);
    }
    if (clusters != 0)
        throw Error("clustered (4-bit) mixture weights are not supported", fileName);
    if (featureCount != streams)
        throw Error("the mixture weights' stream count differs from the Gaussians'", fileName);
    const int32_t rows = r.i32("codeword count"), columns = r.i32("senone count");
    if (rows != densities || columns != senones)
        throw Error("the mixture weights' shape (" + std::to_string(rows) + " x " + std::to_string(columns) +
                        ") differs from the model's (" + std::to_string(densities) + " x " + std::to_string(senones) + ")",
                    fileName);
    const uint64_t size = uint64_t(streams) * uint64_t(densities) * uint64_t(senones);
    r.need(size, "weights");
    return std::vector<uint8_t>(bytes.begin() + std::ptrdiff_t(r.position()), bytes.begin() + std::ptrdiff_t(r.position() + size));
}

SphinxCodebooks SphinxCodebooks::read(const std::string &modelDir, int senones, double logBase, double varianceFloor)
{
    const std::filesystem::path dir(modelDir);
    const std::string meansPath = (dir / "means").string(), variancesPath = (dir / "variances").string();
    const Gaussians means = parseGaussians(readBytes(meansPath), meansPath);
    const Gaussians variances = parseGaussians(readBytes(variancesPath), variancesPath);
    if (variances.codebooks != means.codebooks || variances.streams != means.streams ||
        variances.densities != means.densities || variances.lengths != means.lengths)
        throw Error("the variances' shape differs from the means'", variancesPath);
    SphinxCodebooks c;
    c.m_codebooks = means.codebooks;
    c.m_densities = means.densities;
    c.m_senones = senones;
    c.m_streamLength = means.lengths;
    size_t offset = 0;
    for (int cb = 0; cb < c.m_codebooks; ++cb)
        for (int f = 0; f < c.streams(); ++f) {
            const int length = c.m_streamLength[size_t(f)];
            c.m_means.push_back(Eigen::Map<const Matrix>(means.values.data() + offset, c.m_densities, length));
            // As gauden_dist_precompute: variances below -varfloor are raised to it.
            c.m_variances.push_back(
                Eigen::Map<const Matrix>(variances.values.data() + offset, c.m_densities, length).cwiseMax(float(varianceFloor)));
            offset += size_t(c.m_densities) * size_t(length);
        }
    const std::string sendumpPath = (dir / "sendump").string();
    c.m_weights = parseMixtureWeights(readBytes(sendumpPath), sendumpPath, c.streams(), c.m_densities, senones);
    // The weights are -log_b(w) >> 10 (SENSCR_SHIFT) in the decoder's log base b.
    c.m_weightUnit = 1024.0 * std::log(logBase);
    return c;
}

} // namespace lipsync
