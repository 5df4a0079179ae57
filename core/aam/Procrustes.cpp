#include "aam/Procrustes.h"

#include <Eigen/SVD>

#include <cmath>

namespace lipsync {

Eigen::VectorXd Similarity::apply(const Eigen::VectorXd &shape) const
{
    Eigen::VectorXd out(shape.size());
    for (Eigen::Index i = 0; i + 1 < shape.size(); i += 2) {
        const double x = shape[i], y = shape[i + 1];
        out[i] = a * x - b * y + tx;
        out[i + 1] = b * x + a * y + ty;
    }
    return out;
}

Eigen::Vector2d Similarity::apply(const Eigen::Vector2d &p) const
{
    return {a * p.x() - b * p.y() + tx, b * p.x() + a * p.y() + ty};
}

Similarity Similarity::inverse() const
{
    const double d = a * a + b * b;
    Similarity inv;
    inv.a = a / d;
    inv.b = -b / d;
    inv.tx = -(inv.a * tx - inv.b * ty);
    inv.ty = -(inv.b * tx + inv.a * ty);
    return inv;
}

Similarity Similarity::compose(const Similarity &o) const
{
    Similarity r;
    r.a = a * o.a - b * o.b;
    r.b = b * o.a + a * o.b;
    r.tx = a * o.tx - b * o.ty + tx;
    r.ty = b * o.tx + a * o.ty + ty;
    return r;
}

double Similarity::scale() const
{
    return std::sqrt(a * a + b * b);
}

Eigen::Vector2d shapeCentroid(const Eigen::VectorXd &shape)
{
    const Eigen::Index n = shape.size() / 2;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < n; ++i)
        c += shape.segment<2>(2 * i);
    return n > 0 ? Eigen::Vector2d(c / double(n)) : c;
}

double shapeSize(const Eigen::VectorXd &shape)
{
    const Eigen::Vector2d c = shapeCentroid(shape);
    double sum = 0.0;
    for (Eigen::Index i = 0; i < shape.size() / 2; ++i)
        sum += (shape.segment<2>(2 * i) - c).squaredNorm();
    return std::sqrt(sum);
}

Eigen::VectorXd normalisedShape(const Eigen::VectorXd &shape)
{
    const Eigen::Vector2d c = shapeCentroid(shape);
    Eigen::VectorXd out = shape;
    for (Eigen::Index i = 0; i < shape.size() / 2; ++i)
        out.segment<2>(2 * i) -= c;
    const double s = out.norm();
    return s > 0 ? Eigen::VectorXd(out / s) : out;
}

double shapeSpread(const Eigen::VectorXd &shape)
{
    const Eigen::Index n = shape.size() / 2;
    if (n < 3)
        return 0.0;
    const Eigen::Vector2d c = shapeCentroid(shape);
    Eigen::MatrixX2d centred(n, 2);
    for (Eigen::Index i = 0; i < n; ++i)
        centred.row(i) = (shape.segment<2>(2 * i) - c).transpose();
    Eigen::JacobiSVD<Eigen::MatrixX2d> svd(centred);
    return svd.singularValues()[1] / std::sqrt(double(n));
}

Similarity alignSimilarity(const Eigen::VectorXd &from, const Eigen::VectorXd &to,
                           const Eigen::VectorXd &weights)
{
    const Eigen::Index n = from.size() / 2;
    double wsum = 0.0;
    Eigen::Vector2d cf = Eigen::Vector2d::Zero(), ct = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < n; ++i) {
        const double w = weights.size() ? weights[i] : 1.0;
        wsum += w;
        cf += w * from.segment<2>(2 * i);
        ct += w * to.segment<2>(2 * i);
    }
    Similarity t;
    if (wsum <= 0)
        return t;
    cf /= wsum;
    ct /= wsum;
    double sxx = 0.0, num_a = 0.0, num_b = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const double w = weights.size() ? weights[i] : 1.0;
        const Eigen::Vector2d p = from.segment<2>(2 * i) - cf;
        const Eigen::Vector2d q = to.segment<2>(2 * i) - ct;
        sxx += w * p.squaredNorm();
        num_a += w * (p.x() * q.x() + p.y() * q.y());
        num_b += w * (p.x() * q.y() - p.y() * q.x());
    }
    if (sxx <= 1e-300) {
        t.tx = ct.x() - cf.x();
        t.ty = ct.y() - cf.y();
        return t;
    }
    t.a = num_a / sxx;
    t.b = num_b / sxx;
    t.tx = ct.x() - (t.a * cf.x() - t.b * cf.y());
    t.ty = ct.y() - (t.b * cf.x() + t.a * cf.y());
    return t;
}

ProcrustesResult generalisedProcrustes(const std::vector<Eigen::VectorXd> &shapes,
                                       int maxIterations, double tolerance)
{
    ProcrustesResult result;
    if (shapes.empty())
        return result;
    const Eigen::VectorXd reference = normalisedShape(shapes.front());
    Eigen::VectorXd mean = reference;
    result.aligned.resize(shapes.size());
    for (int it = 0; it < maxIterations; ++it) {
        result.iterations = it + 1;
        Eigen::VectorXd sum = Eigen::VectorXd::Zero(mean.size());
        for (size_t i = 0; i < shapes.size(); ++i) {
            result.aligned[i] = alignSimilarity(shapes[i], mean).apply(shapes[i]);
            sum += result.aligned[i];
        }
        Eigen::VectorXd next = normalisedShape(sum / double(shapes.size()));
        // Keep the mean in the reference orientation so the iteration cannot drift.
        next = alignSimilarity(next, reference).apply(next);
        next = normalisedShape(next);
        const double change = (next - mean).norm();
        mean = next;
        if (change < tolerance)
            break;
    }
    for (auto &x : result.aligned) {
        x = alignSimilarity(x, mean).apply(x);
        const double d = x.dot(mean);
        if (d > 0)
            x /= d; // tangent space projection
    }
    result.mean = mean;
    return result;
}

} // namespace lipsync
