#include "align/TrainingStatistics.h"

#include "io/AtomicFile.h"
#include "util/Error.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace lipsync {

namespace {

constexpr char kMagic[8] = {'L', 'S', 'T', 'A', 'T', 'S', '0', '1'};

class Writer
{
public:
    template<class T>
    void put(T v)
    {
        char bytes[sizeof(T)];
        std::memcpy(bytes, &v, sizeof(T));
        out.append(bytes, sizeof(T));
    }
    void doubles(const double *v, Eigen::Index n)
    {
        for (Eigen::Index i = 0; i < n; ++i)
            put<double>(v[i]);
    }
    std::string out;
};

class Reader
{
public:
    Reader(const std::string &bytes, const std::string &path) : m_bytes(bytes), m_path(path) {}

    template<class T>
    T get()
    {
        need(sizeof(T));
        T v;
        std::memcpy(&v, m_bytes.data() + m_at, sizeof(T));
        m_at += sizeof(T);
        return v;
    }
    // `n` doubles, each finite.
    void doubles(double *v, Eigen::Index n)
    {
        need(size_t(n) * sizeof(double));
        for (Eigen::Index i = 0; i < n; ++i) {
            v[i] = get<double>();
            if (!std::isfinite(v[i]))
                throw Error("a statistic is not a finite number", m_path);
        }
    }
    std::string text(uint64_t length)
    {
        need(length);
        std::string s = m_bytes.substr(m_at, size_t(length));
        m_at += size_t(length);
        return s;
    }
    bool atEnd() const { return m_at == m_bytes.size(); }

private:
    // Checked before anything is allocated for it: a damaged length cannot ask for more.
    void need(uint64_t n) const
    {
        if (n > m_bytes.size() - m_at)
            throw Error("truncated aligner training statistics", m_path);
    }
    const std::string &m_bytes;
    const std::string &m_path;
    size_t m_at = 0;
};

} // namespace

void TrainingStatistics::add(const TrainingStatistics &other)
{
    if (other.kind != kind)
        throw Error("flat-start statistics and Baum-Welch statistics cannot be merged");
    if (other.model.text() != model.text())
        throw Error(kind == Kind::BaumWelch ? "the statistics were collected under another model"
                                            : "the statistics were computed with other feature options");
    if (kind == Kind::FlatStart)
        flatStart.add(other.flatStart);
    else
        baumWelch->add(*other.baumWelch);
}

void writeTrainingStatistics(const std::string &path, const TrainingStatistics &st)
{
    Writer w;
    w.out.append(kMagic, sizeof kMagic);
    w.put<uint32_t>(uint32_t(st.kind));
    const std::string text = st.model.text();
    w.put<uint64_t>(text.size());
    w.out += text;
    if (st.kind == TrainingStatistics::Kind::FlatStart) {
        const FlatStartStatistics &f = st.flatStart;
        w.put<int64_t>(f.frames[0]);
        w.put<int64_t>(f.frames[1]);
        const Eigen::Index d = f.sum[0].size() ? f.sum[0].size() : f.sum[1].size();
        w.put<uint32_t>(uint32_t(d));
        for (int k = 0; k < 2; ++k) {
            const Eigen::VectorXd sum = f.sum[k].size() ? f.sum[k] : Eigen::VectorXd::Zero(d);
            const Eigen::VectorXd squares = f.sumSquares[k].size() ? f.sumSquares[k] : Eigen::VectorXd::Zero(d);
            w.doubles(sum.data(), d);
            w.doubles(squares.data(), d);
        }
    } else {
        const Accumulators &a = *st.baumWelch;
        w.put<double>(a.logLikelihood);
        w.put<int64_t>(a.frames);
        w.put<int32_t>(a.utterances);
        for (const StateAccumulator &s : a.states) {
            w.put<double>(s.occupancy);
            w.put<double>(s.selfCount);
            w.doubles(s.componentOccupancy.data(), s.componentOccupancy.size());
            w.doubles(s.sum.data(), s.sum.size());
            w.doubles(s.sumSquares.data(), s.sumSquares.size());
        }
    }
    writeFileAtomically(path, w.out);
}

TrainingStatistics parseTrainingStatistics(const std::string &bytes, const std::string &path)
{
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw Error("not aligner training statistics (lipsync aligner train --accumulate-only)", path);
    Reader r(bytes, path);
    r.text(sizeof kMagic);
    TrainingStatistics st;
    const uint32_t kind = r.get<uint32_t>();
    if (kind != uint32_t(TrainingStatistics::Kind::FlatStart) && kind != uint32_t(TrainingStatistics::Kind::BaumWelch))
        throw Error("unknown kind of aligner training statistics " + std::to_string(kind), path);
    st.kind = TrainingStatistics::Kind(kind);
    st.model = AcousticModel::parse(r.text(r.get<uint64_t>()), path);
    if (st.kind == TrainingStatistics::Kind::FlatStart) {
        FlatStartStatistics &f = st.flatStart;
        f.frames[0] = r.get<int64_t>();
        f.frames[1] = r.get<int64_t>();
        const uint32_t d = r.get<uint32_t>();
        if (f.frames[0] < 0 || f.frames[1] < 0 || int(d) != st.model.dimension())
            throw Error("flat-start statistics that do not fit their feature options", path);
        for (int k = 0; k < 2; ++k) {
            f.sum[k] = Eigen::VectorXd(d);
            f.sumSquares[k] = Eigen::VectorXd(d);
            r.doubles(f.sum[k].data(), d);
            r.doubles(f.sumSquares[k].data(), d);
        }
    } else {
        Accumulators a(st.model);
        a.logLikelihood = r.get<double>();
        a.frames = r.get<int64_t>();
        a.utterances = r.get<int32_t>();
        if (!std::isfinite(a.logLikelihood) || a.frames < 0 || a.utterances < 0)
            throw Error("damaged Baum-Welch statistics", path);
        for (StateAccumulator &s : a.states) {
            r.doubles(&s.occupancy, 1);
            r.doubles(&s.selfCount, 1);
            r.doubles(s.componentOccupancy.data(), s.componentOccupancy.size());
            r.doubles(s.sum.data(), s.sum.size());
            r.doubles(s.sumSquares.data(), s.sumSquares.size());
            if (s.occupancy < 0 || s.selfCount < 0 || (s.componentOccupancy.array() < 0).any())
                throw Error("damaged Baum-Welch statistics (a negative count)", path);
        }
        st.baumWelch = std::move(a);
    }
    if (!r.atEnd())
        throw Error("aligner training statistics followed by other data", path);
    return st;
}

TrainingStatistics readTrainingStatistics(const std::string &path)
{
    return parseTrainingStatistics(readWholeFile(path), path);
}

} // namespace lipsync
