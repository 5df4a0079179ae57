#include "dynamics/LinearRecursion.h"

#include "dynamics/LabelledSequence.h"

namespace lipsync {

void LinearRecursion::step(int label, const Eigen::VectorXd &previous,
                           Eigen::Ref<Eigen::VectorXd> y) const
{
    if (full.empty())
        y = a.row(label).transpose().cwiseProduct(previous) + nu.row(label).transpose();
    else
        y.noalias() = full[size_t(label)] * previous + nu.row(label).transpose();
}

Eigen::MatrixXd LinearRecursion::generate(const std::vector<int> &labels) const
{
    const Eigen::Index T = Eigen::Index(labels.size());
    const int d = dimension();
    // Column-major T x d would stride the per-frame writes; build d x T and transpose.
    Eigen::MatrixXd out(d, T);
    Eigen::VectorXd y(d);
    Eigen::VectorXd next(d);
    first(labels[0], y);
    out.col(0) = y;
    for (Eigen::Index t = 1; t < T; ++t) {
        step(labels[size_t(t)], y, next);
        y.swap(next);
        out.col(t) = y;
    }
    return out.transpose();
}

namespace {
class RecursionStreamer : public StreamingGenerator
{
public:
    explicit RecursionStreamer(const LinearRecursion &r)
        : m_r(r), m_y(r.dimension()), m_next(r.dimension())
    {
    }
    int latency() const override { return 0; }
    void push(int label) override
    {
        checkStateLabel(label, int(m_r.mu.rows()));
        if (!m_started) {
            m_r.first(label, m_y);
            m_started = true;
        } else {
            m_r.step(label, m_y, m_next);
            m_y.swap(m_next);
        }
        m_ready = true;
    }
    void finish() override {}
    bool pop(Eigen::Ref<Eigen::VectorXd> frame) override
    {
        if (!m_ready)
            return false;
        frame = m_y;
        m_ready = false;
        return true;
    }

private:
    // A copy: the streamer stays valid if the model is retrained or destroyed.
    LinearRecursion m_r;
    Eigen::VectorXd m_y;
    Eigen::VectorXd m_next;
    bool m_started = false;
    bool m_ready = false;
};
} // namespace

std::unique_ptr<StreamingGenerator> LinearRecursion::streamer() const
{
    return std::make_unique<RecursionStreamer>(*this);
}

} // namespace lipsync
