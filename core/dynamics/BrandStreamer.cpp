#include "dynamics/BrandStreamer.h"

#include "dynamics/BrandModel.h"
#include "util/Error.h"

#include <Eigen/Cholesky>

#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace lipsync {

struct FixedLagStreamers::Shared
{
    explicit Shared(const BrandModel &m) : model(m), terms(static_cast<size_t>(m.stateCount())) {}
    BrandModel model; // a copy: the streamers outlive a retrained model
    std::vector<std::shared_ptr<const brand::BlockTerms>> terms; // per state, once seen after frame 1
};

namespace {

// What both fixed-lag streamers share (§5): one row per label, row t of the forward LDL^T sweep
// finalised once label t+1 is in; frame t emitted once label h = t + L is in, from the solve
// truncated at h (row h closed as if it ended the sequence); rows no longer needed dropped.
template<class Row>
class FixedLagStreamer : public StreamingGenerator
{
public:
    explicit FixedLagStreamer(int lag) : m_lag(lag) {}
    int latency() const override { return m_lag; }

    void finish() override
    {
        if (m_finished)
            return;
        m_finished = true;
        const long h = m_base + long(m_rows.size()) - 1;
        if (h >= m_next)
            emitUpTo(h, h);
    }

    bool pop(Eigen::Ref<Eigen::VectorXd> frame) override { return m_ready.pop(frame); }

protected:
    void checkOpen() const
    {
        if (m_finished)
            throw Error("streamer already finished");
    }
    bool atFirstFrame() const { return m_rows.empty() && m_base == 0; }
    void append(Row row)
    {
        m_rows.push_back(std::move(row));
        const long h = m_base + long(m_rows.size()) - 1;
        if (h > 0)
            finaliseRow(h - 1);
        if (h - m_lag >= m_next)
            emitUpTo(h, m_next);
    }
    Row &row(long t) { return m_rows[size_t(t - m_base)]; }

    // Row t gets what label t+1 adds to it, and the sweep's step through it.
    virtual void finaliseRow(long t) = 0;
    // Frames from..h of the solve truncated at h.
    virtual std::vector<Eigen::VectorXd> truncatedSolve(long h, long from) = 0;

private:
    void emitUpTo(long h, long last)
    {
        const std::vector<Eigen::VectorXd> y = truncatedSolve(h, m_next);
        for (long t = m_next; t <= last; ++t)
            m_ready.push(y[size_t(t - m_next)]);
        m_next = last + 1;
        // Rows before m_next - 2 are no longer needed (rows m_next - 2 and m_next - 1 feed the next
        // finalised row and pivot).
        while (m_base < m_next - 2) {
            m_rows.pop_front();
            ++m_base;
        }
    }

    int m_lag;
    std::deque<Row> m_rows;
    long m_base = 0; // frame index of m_rows.front()
    long m_next = 0; // next frame to emit
    bool m_finished = false;
    ReadyFrames m_ready;
};

struct DiagonalRow
{
    Eigen::ArrayXd p, pm, q, qd; // p_t, p_t mbar_t, q_t, q_t deltabar_t
    Eigen::ArrayXd pivot, l, z;  // set once row t+1's label is known
};

// Fixed-lag MLPG for diagonal covariances: the tridiagonal sweep of §2.2, vectorised over the d
// dimensions.
class FixedLagBrandStreamer : public FixedLagStreamer<DiagonalRow>
{
public:
    FixedLagBrandStreamer(std::shared_ptr<const FixedLagStreamers::Shared> shared, int lag)
        : FixedLagStreamer(lag), m_shared(std::move(shared)), m_pInv(m_shared->model.staticVariance),
          m_mean(m_shared->model.staticMean), m_qInv(m_shared->model.deltaVariance), m_delta(m_shared->model.deltaMean)
    {
    }

    void push(int label) override
    {
        checkOpen();
        checkStateLabel(label, int(m_mean.rows()));
        DiagonalRow r;
        r.p = m_pInv.row(label).transpose().array().inverse();
        r.pm = r.p * m_mean.row(label).transpose().array();
        if (atFirstFrame()) {
            r.q = Eigen::ArrayXd::Zero(r.p.size());
            r.qd = r.q;
        } else {
            r.q = m_qInv.row(label).transpose().array().inverse();
            r.qd = r.q * m_delta.row(label).transpose().array();
        }
        append(std::move(r));
    }

private:
    // Row t of H needs q_{t+1}: alpha_t = p_t + q_t + q_{t+1}, beta_t = -q_{t+1}.
    void finaliseRow(long t) override
    {
        DiagonalRow &r = row(t);
        const DiagonalRow &next = row(t + 1);
        const Eigen::ArrayXd alpha = r.p + r.q + next.q;
        const Eigen::ArrayXd b = r.pm + r.qd - next.qd;
        if (t == 0) {
            r.l = Eigen::ArrayXd::Zero(r.p.size());
            r.pivot = alpha;
            r.z = b;
        } else {
            const DiagonalRow &prev = row(t - 1);
            const Eigen::ArrayXd beta = -r.q; // beta_{t-1}
            r.l = beta / prev.pivot;
            r.pivot = alpha - r.l * beta;
            r.z = b - r.l * prev.z;
        }
    }

    std::vector<Eigen::VectorXd> truncatedSolve(long h, long from) override
    {
        const DiagonalRow &end = row(h);
        Eigen::ArrayXd pivot = end.p + end.q, z = end.pm + end.qd, lEnd;
        if (h > 0) {
            const DiagonalRow &prev = row(h - 1);
            const Eigen::ArrayXd beta = -end.q;
            lEnd = beta / prev.pivot;
            pivot -= lEnd * beta;
            z -= lEnd * prev.z;
        }
        std::vector<Eigen::VectorXd> y(size_t(h - from + 1));
        y.back() = (z / pivot).matrix();
        for (long tau = h - 1; tau >= from; --tau) {
            const Eigen::ArrayXd &lNext = tau + 1 == h ? lEnd : row(tau + 1).l;
            y[size_t(tau - from)] =
                (row(tau).z / row(tau).pivot - lNext * y[size_t(tau + 1 - from)].array()).matrix();
        }
        return y;
    }

    std::shared_ptr<const FixedLagStreamers::Shared> m_shared;
    const Eigen::MatrixXd &m_pInv, &m_mean, &m_qInv, &m_delta; // the model's variances and means (P x d)
};

struct BlockRow
{
    std::shared_ptr<const brand::BlockTerms> terms;
    Eigen::LLT<Eigen::MatrixXd> pivot; // D_t, once row t+1's label is known
    Eigen::MatrixXd l;                 // L_t = H_{t,t-1} D_{t-1}^{-1} (t >= 1), with D_{t-1}
    Eigen::VectorXd z;
};

// Fixed-lag MLPG for full covariances: the block LDL^T sweep of §2.2 (a Cholesky factor per pivot
// block), L_{t+1} computed with D_t. O(L d^2) per frame after one d x d factorisation.
class FixedLagBlockBrandStreamer : public FixedLagStreamer<BlockRow>
{
public:
    FixedLagBlockBrandStreamer(std::shared_ptr<FixedLagStreamers::Shared> shared, int lag)
        : FixedLagStreamer(lag), m_shared(std::move(shared))
    {
    }

    void push(int label) override
    {
        checkOpen();
        const BrandModel &model = m_shared->model;
        checkStateLabel(label, model.stateCount());
        BlockRow r;
        if (atFirstFrame()) {
            r.terms = std::make_shared<const brand::BlockTerms>(model.blockTerms(label, true));
        } else {
            std::shared_ptr<const brand::BlockTerms> &cached = m_shared->terms[size_t(label)];
            if (!cached)
                cached = std::make_shared<const brand::BlockTerms>(model.blockTerms(label, false));
            r.terms = cached;
        }
        append(std::move(r));
    }

private:
    static void checkPivot(const Eigen::LLT<Eigen::MatrixXd> &pivot, long t)
    {
        if (pivot.info() != Eigen::Success)
            throw Error("block pivot " + std::to_string(t) + " is not positive definite");
    }

    // Row t gets frame t+1's terms: H_tt = its own + next's previousDiagonal, likewise the rhs.
    void finaliseRow(long t) override
    {
        BlockRow &r = row(t);
        BlockRow &next = row(t + 1);
        const Eigen::MatrixXd H = r.terms->diagonal + next.terms->previousDiagonal;
        const Eigen::VectorXd b = r.terms->rhs + next.terms->previousRhs;
        if (t == 0) {
            r.pivot.compute(H);
            r.z = b;
        } else {
            r.pivot.compute(H - r.l * r.terms->lower.transpose());
            r.z = b - r.l * row(t - 1).z;
        }
        checkPivot(r.pivot, t);
        next.l = r.pivot.solve(next.terms->lower.transpose()).transpose();
    }

    std::vector<Eigen::VectorXd> truncatedSolve(long h, long from) override
    {
        const BlockRow &end = row(h);
        Eigen::MatrixXd pivot = end.terms->diagonal;
        Eigen::VectorXd z = end.terms->rhs;
        if (h > 0) {
            pivot -= end.l * end.terms->lower.transpose();
            z -= end.l * row(h - 1).z;
        }
        const Eigen::LLT<Eigen::MatrixXd> closing(pivot);
        checkPivot(closing, h);
        std::vector<Eigen::VectorXd> y(size_t(h - from + 1));
        y.back() = closing.solve(z);
        for (long tau = h - 1; tau >= from; --tau)
            y[size_t(tau - from)] = row(tau).pivot.solve(row(tau).z) - row(tau + 1).l.transpose() * y[size_t(tau + 1 - from)];
        return y;
    }

    std::shared_ptr<FixedLagStreamers::Shared> m_shared;
};

} // namespace

FixedLagStreamers::FixedLagStreamers(const BrandModel &model) : m_shared(std::make_shared<Shared>(model)) {}

FixedLagStreamers::~FixedLagStreamers() = default;

std::unique_ptr<StreamingGenerator> FixedLagStreamers::make(int lag) const
{
    if (m_shared->model.fullCovariance())
        return std::make_unique<FixedLagBlockBrandStreamer>(m_shared, lag);
    return std::make_unique<FixedLagBrandStreamer>(m_shared, lag);
}

} // namespace lipsync
