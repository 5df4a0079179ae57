#include "align/AcousticModel.h"

#include "util/PhoneSet.h"
#include "io/AtomicFile.h"
#include "io/AudioDecoder.h"
#include "util/Error.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace lipsync {

namespace {
constexpr double kLog2Pi = 1.8378770664093453;
}

void GaussianMixture::prepare()
{
    const int m = size();
    const int d = int(means.cols());
    precisions = variances.cwiseInverse();
    logConstants.resize(m);
    for (int i = 0; i < m; ++i) {
        const double logDet = variances.row(i).array().log().sum();
        logConstants[i] = float(std::log(std::max(double(weights[i]), 1e-30)) - 0.5 * (d * kLog2Pi + logDet));
    }
}

float GaussianMixture::componentLogLikelihoods(const float *x, float *out) const
{
    const int m = size();
    const int d = int(means.cols());
    float best = -INFINITY;
    for (int i = 0; i < m; ++i) {
        const float *mean = means.data() + size_t(i) * size_t(d);
        const float *precision = precisions.data() + size_t(i) * size_t(d);
        float sum = 0;
        for (int k = 0; k < d; ++k) {
            const float diff = x[k] - mean[k];
            sum += diff * diff * precision[k];
        }
        out[i] = logConstants[i] - 0.5f * sum;
        best = std::max(best, out[i]);
    }
    if (m == 1)
        return out[0];
    float total = 0;
    for (int i = 0; i < m; ++i)
        total += std::exp(out[i] - best);
    return best + std::log(total);
}

float GaussianMixture::logLikelihood(const float *x) const
{
    float buffer[64];
    std::vector<float> heap;
    float *out = buffer;
    if (size() > 64) {
        heap.resize(size_t(size()));
        out = heap.data();
    }
    return componentLogLikelihoods(x, out);
}

AcousticModel::AcousticModel(const MfccOptions &features, CepstralNormalization normalization,
                             const Eigen::VectorXf &mean, const Eigen::VectorXf &variance, double selfLoop)
    : m_features(features), m_normalization(normalization), m_dimension(int(mean.size()))
{
    const int states = PhoneSet::kCount * kStatesPerPhone;
    m_states.resize(size_t(states));
    m_selfLoop.assign(size_t(states), selfLoop);
    for (GaussianMixture &g : m_states) {
        g.weights = Eigen::VectorXf::Ones(1);
        g.means = mean.transpose();
        g.variances = variance.transpose();
    }
    m_varianceFloor = 0.01f * variance;
    prepare();
}

void AcousticModel::prepare()
{
    for (GaussianMixture &g : m_states)
        g.prepare();
    if (!m_mfcc || !(m_mfcc->options() == m_features))
        m_mfcc = std::make_shared<const Mfcc>(m_features);
}

Eigen::MatrixXf AcousticModel::features(const std::vector<float> &samples) const
{
    Eigen::MatrixXf f = m_mfcc->compute(samples);
    // Digital silence (every filter bank at the log floor, so every static coefficient exactly 0)
    // is no recording at all: the stretch before a stream starts late or a timestamp gap the
    // decoder filled (AudioTimeline). It says nothing about the speaker or the channel, so the
    // per-utterance statistics are taken over the other frames.
    const int s = m_mfcc->staticDimension();
    std::vector<Eigen::Index> recorded;
    for (Eigen::Index t = 0; t < f.rows(); ++t)
        if (!(f.row(t).leftCols(s).array() == 0.0f).all())
            recorded.push_back(t);
    auto columnMean = [&](const Eigen::MatrixXf &m) -> Eigen::RowVectorXf {
        if (recorded.empty() || recorded.size() == size_t(m.rows()))
            return m.colwise().mean();
        Eigen::RowVectorXf sum = Eigen::RowVectorXf::Zero(m.cols());
        for (Eigen::Index t : recorded)
            sum += m.row(t);
        return sum / float(recorded.size());
    };
    if (m_normalization != CepstralNormalization::None && f.rows() > 0) {
        const Eigen::RowVectorXf mean = columnMean(f.leftCols(s));
        f.leftCols(s).rowwise() -= mean;
    }
    if (m_normalization == CepstralNormalization::MeanAndVariance && f.rows() > 1) {
        // Deltas and accelerations have (near) zero mean already; scale every column to unit
        // variance about its mean, with a floor so a constant column stays finite.
        const Eigen::RowVectorXf mean = columnMean(f);
        const Eigen::RowVectorXf sd =
            columnMean((f.rowwise() - mean).array().square().matrix()).array().sqrt().max(1e-3f);
        f.array().rowwise() /= sd.array();
    }
    return f;
}

Eigen::MatrixXf AcousticModel::features(const AudioBuffer &audio) const
{
    if (audio.sampleRate != m_features.sampleRate)
        throw Error("audio at " + std::to_string(audio.sampleRate) + " Hz, the aligner model expects "
                    + std::to_string(m_features.sampleRate) + " Hz");
    return features(audio.samples);
}

void AcousticModel::save(const std::string &path) const
{
    writeFileAtomically(path, text());
}

std::string AcousticModel::text() const
{
    std::string out;
    out.reserve(1 << 20);
    char buffer[64];
    auto number = [&](double v) {
        std::snprintf(buffer, sizeof buffer, " %.9g", v); // every float exactly
        out += buffer;
    };
    const MfccOptions &f = m_features;
    out += "lipsync-aligner " + std::to_string(m_boundaries.empty() ? 1 : kFormatVersion) + "\n";
    out += "# Monophone HMMs (3 emitting states, diagonal GMMs) over MFCC_0_D_A; see core/align/AcousticModel.h\n";
    out += "features";
    number(f.sampleRate), number(f.windowSeconds), number(f.shiftSeconds), number(f.preemphasis);
    number(f.melChannels), number(f.cepstra), number(f.lifter), number(f.deltaWindow);
    number(int(m_normalization));
    out += "\ndimension " + std::to_string(m_dimension) + "\nfloor";
    for (int k = 0; k < m_varianceFloor.size(); ++k)
        number(m_varianceFloor[k]);
    out += "\n";
    for (int p = 0; p < PhoneSet::kCount; ++p) {
        out += "phone " + PhoneSet::label(p) + "\n";
        for (int s = 0; s < kStatesPerPhone; ++s) {
            const int index = stateIndex(p, s);
            const GaussianMixture &g = m_states[size_t(index)];
            out += "state " + std::to_string(s) + " mixtures " + std::to_string(g.size()) + " selfloop";
            std::snprintf(buffer, sizeof buffer, " %.17g", m_selfLoop[size_t(index)]); // a double
            out += buffer;
            out += "\n";
            for (int m = 0; m < g.size(); ++m) {
                out += "w";
                number(g.weights[m]);
                out += "\nm";
                for (int k = 0; k < m_dimension; ++k)
                    number(g.means(m, k));
                out += "\nv";
                for (int k = 0; k < m_dimension; ++k)
                    number(g.variances(m, k));
                out += "\n";
            }
        }
    }
    if (!m_boundaries.empty()) {
        const std::vector<std::string> lines = m_boundaries.lines();
        out += "boundaries minimum " + std::to_string(m_boundaries.minimumCount()) + " entries "
               + std::to_string(lines.size()) + "\n";
        for (const std::string &line : lines)
            out += "b " + line + "\n";
    }
    return out;
}

AcousticModel AcousticModel::load(const std::string &path)
{
    return parse(readWholeFile(path), path);
}

namespace {

// The lines of a model file, comments and blank lines skipped, with errors that name the file and
// the line.
class ModelTextReader
{
public:
    ModelTextReader(const std::string &text, const std::string &path) : m_in(text), m_path(path) {}

    Error fail(const std::string &what) const { return Error(what, m_path, "line " + std::to_string(m_lineNumber)); }

    // The next line's fields. One stream re-filled for every line: constructing a stream per line
    // (its locale and facets) would be most of the cost of parsing a small model; a line's stream
    // is valid until the next call.
    std::istringstream &next()
    {
        while (std::getline(m_in, m_line)) {
            ++m_lineNumber;
            if (!m_line.empty() && m_line.back() == '\r')
                m_line.pop_back();
            if (!m_line.empty() && m_line[0] != '#') {
                m_fields.clear();
                m_fields.str(m_line);
                return m_fields;
            }
        }
        ++m_lineNumber;
        throw fail("unexpected end of file");
    }

    void expectKey(std::istringstream &s, const std::string &key) const
    {
        std::string k;
        if (!(s >> k) || k != key)
            throw fail("expected '" + key + "'");
    }

    // The next line: `key` and n finite numbers.
    Eigen::VectorXf readVector(const std::string &key, int n)
    {
        std::istringstream &s = next();
        expectKey(s, key);
        Eigen::VectorXf v(n);
        for (int k = 0; k < n; ++k)
            if (!(s >> v[k]) || !std::isfinite(v[k]))
                throw fail("expected " + std::to_string(n) + " numbers after '" + key + "'");
        return v;
    }

private:
    std::istringstream m_in;
    std::string m_path;
    std::string m_line;
    int m_lineNumber = 0;
    std::istringstream m_fields;
};

} // namespace

AcousticModel AcousticModel::parse(const std::string &text, const std::string &path)
{
    ModelTextReader reader(text, path);
    AcousticModel model;
    int version = 0;
    {
        std::istringstream &s = reader.next();
        std::string magic;
        if (!(s >> magic >> version) || magic != "lipsync-aligner")
            throw reader.fail("not a lipsync aligner model");
        if (version < 1 || version > kFormatVersion)
            throw reader.fail("unsupported aligner model version " + std::to_string(version));
    }
    {
        std::istringstream &s = reader.next();
        reader.expectKey(s, "features");
        MfccOptions &f = model.m_features;
        double normalize = 0;
        if (!(s >> f.sampleRate >> f.windowSeconds >> f.shiftSeconds >> f.preemphasis >> f.melChannels
              >> f.cepstra >> f.lifter >> f.deltaWindow >> normalize))
            throw reader.fail("bad feature configuration");
        if (normalize != 0 && normalize != 1 && normalize != 2)
            throw reader.fail("unknown feature normalisation " + std::to_string(normalize) + " (0 none, 1 mean, 2 mean and variance)");
        model.m_normalization = CepstralNormalization(int(normalize));
    }
    {
        std::istringstream &s = reader.next();
        reader.expectKey(s, "dimension");
        if (!(s >> model.m_dimension) || model.m_dimension <= 0 || model.m_dimension > 1000)
            throw reader.fail("bad dimension");
    }
    const int d = model.m_dimension;
    model.m_varianceFloor = reader.readVector("floor", d);
    const int states = PhoneSet::kCount * kStatesPerPhone;
    model.m_states.resize(size_t(states));
    model.m_selfLoop.assign(size_t(states), 0.6);
    for (int p = 0; p < PhoneSet::kCount; ++p) {
        std::istringstream &s = reader.next();
        reader.expectKey(s, "phone");
        std::string label;
        s >> label;
        if (label != PhoneSet::label(p))
            throw reader.fail("expected phone " + PhoneSet::label(p) + ", found '" + label + "'");
        for (int st = 0; st < kStatesPerPhone; ++st) {
            std::istringstream &h = reader.next();
            int position = -1, mixtures = 0;
            double selfLoop = 0;
            std::string k1, k2, k3;
            if (!(h >> k1 >> position >> k2 >> mixtures >> k3 >> selfLoop) || k1 != "state"
                || k2 != "mixtures" || k3 != "selfloop" || position != st || mixtures < 1 || mixtures > 1024
                || !(selfLoop > 0 && selfLoop < 1))
                throw reader.fail("expected 'state " + std::to_string(st) + " mixtures M selfloop P'");
            const int index = stateIndex(p, st);
            model.m_selfLoop[size_t(index)] = selfLoop;
            GaussianMixture &g = model.m_states[size_t(index)];
            g.weights.resize(mixtures);
            g.means.resize(mixtures, d);
            g.variances.resize(mixtures, d);
            for (int m = 0; m < mixtures; ++m) {
                g.weights[m] = reader.readVector("w", 1)[0];
                g.means.row(m) = reader.readVector("m", d).transpose();
                g.variances.row(m) = reader.readVector("v", d).transpose();
                if (!(g.variances.row(m).array() > 0).all())
                    throw reader.fail("variances must be positive");
            }
        }
    }
    if (version >= 2) {
        std::istringstream &s = reader.next();
        std::string k1, k2, k3;
        int minimum = 0, entries = -1;
        if (!(s >> k1 >> k2 >> minimum >> k3 >> entries) || k1 != "boundaries" || k2 != "minimum"
            || k3 != "entries" || minimum < 1 || entries < 1 || entries > 1000000)
            throw reader.fail("expected 'boundaries minimum M entries N'");
        model.m_boundaries.setMinimumCount(minimum);
        for (int i = 0; i < entries; ++i) {
            std::istringstream &b = reader.next();
            reader.expectKey(b, "b");
            std::string rest;
            std::getline(b, rest);
            try {
                model.m_boundaries.addLine(rest);
            } catch (const std::invalid_argument &e) {
                throw reader.fail(e.what());
            }
        }
    }
    try {
        model.prepare();
    } catch (const Error &e) {
        throw Error(e.reason(), path, "features");
    }
    return model;
}

} // namespace lipsync
