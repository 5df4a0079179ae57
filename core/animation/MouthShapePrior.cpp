#include "animation/MouthShapePrior.h"

#include "aam/Procrustes.h"
#include "animation/MouthTrack.h"
#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <Eigen/Dense>

#include <cmath>

namespace lipsync {

namespace {

constexpr const char *kFormat = "lipsync-mouth-prior";
constexpr int kPoints = 46;

// Per-phone sums and counts of the rows of each track's `points` (or `features`).
struct PhoneSums
{
    Eigen::MatrixXd sum;   // 41 x d
    Eigen::VectorXd count; // 41
    Eigen::VectorXd all;
    double total = 0;

    PhoneSums(const std::vector<MouthTrack> &tracks, bool points)
    {
        const Eigen::Index d = tracks.empty() ? 0 : (points ? tracks.front().points.cols() : tracks.front().features.cols());
        sum = Eigen::MatrixXd::Zero(PhoneSet::kCount, d);
        count = Eigen::VectorXd::Zero(PhoneSet::kCount);
        all = Eigen::VectorXd::Zero(d);
        for (const MouthTrack &t : tracks) {
            const Eigen::MatrixXd &m = points ? t.points : t.features;
            for (int f = 0; f < t.frameCount(); ++f) {
                const int p = t.phones[size_t(f)];
                if (p < 0 || p >= PhoneSet::kCount)
                    continue;
                sum.row(p) += m.row(f);
                count(p) += 1;
                all += m.row(f).transpose();
                total += 1;
            }
        }
    }
    Eigen::VectorXd mean() const { return all / std::max(total, 1.0); }
    Eigen::VectorXd mean(int p) const { return count(p) > 0 ? Eigen::VectorXd(sum.row(p).transpose() / count(p)) : mean(); }
};

QJsonArray toJson(const Eigen::VectorXd &v)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        a.append(v(i));
    return a;
}

Eigen::VectorXd fromJson(const QJsonValue &value, Eigen::Index size, const std::string &path, const std::string &what)
{
    const QJsonArray a = value.toArray();
    if (a.size() != size)
        throw Error(what + ": expected " + std::to_string(size) + " numbers", path);
    Eigen::VectorXd v(size);
    for (Eigen::Index i = 0; i < size; ++i) {
        if (!a[int(i)].isDouble() || !std::isfinite(a[int(i)].toDouble()))
            throw Error(what + ": not a finite number at " + std::to_string(i), path);
        v(i) = a[int(i)].toDouble();
    }
    return v;
}

} // namespace

MouthShapePrior MouthShapePrior::learn(const std::vector<MouthTrack> &tracks)
{
    const PhoneSums points(tracks, true);
    if (points.total == 0 || points.sum.cols() != kPoints)
        throw Error("no tracked, aligned frames to learn mouth shapes from");
    MouthShapePrior prior;
    prior.m_mean = points.mean();
    const double size = shapeSize(prior.m_mean);
    if (!(size > 0))
        throw Error("the tracked frames' mean mouth shape is degenerate");
    prior.m_displacement = Eigen::MatrixXd::Zero(PhoneSet::kCount, kPoints);
    for (int p = 0; p < PhoneSet::kCount; ++p)
        if (points.count(p) > 0)
            prior.m_displacement.row(p) = (points.mean(p) - prior.m_mean).transpose() / size;
    prior.m_frames = points.count;
    return prior;
}

Eigen::MatrixXd MouthShapePrior::personMeans(const std::vector<MouthTrack> &tracks, double kappa) const
{
    const PhoneSums points(tracks, true), features(tracks, false);
    const Eigen::Index d = features.sum.cols();
    if (points.total < double(kPoints) || d == 0)
        throw Error("too few tracked, aligned frames to carry the mouth prior to this face (" +
                    std::to_string(int(points.total)) + ")");
    const Eigen::VectorXd mean = points.mean(), featureMean = features.mean();
    // Points to parameters on the person's own frames: least squares, centred, lightly regularised.
    Eigen::MatrixXd X(Eigen::Index(points.total), kPoints), Y(Eigen::Index(points.total), d);
    Eigen::Index r = 0;
    for (const MouthTrack &t : tracks)
        for (int f = 0; f < t.frameCount(); ++f)
            if (t.phones[size_t(f)] >= 0 && t.phones[size_t(f)] < PhoneSet::kCount) {
                X.row(r) = t.points.row(f) - mean.transpose();
                Y.row(r++) = t.features.row(f) - featureMean.transpose();
            }
    const double ridge = 1e-6 * X.squaredNorm() / double(X.rows());
    const Eigen::MatrixXd W =
        (X.transpose() * X + ridge * Eigen::MatrixXd::Identity(kPoints, kPoints)).ldlt().solve(X.transpose() * Y);
    const double size = shapeSize(mean);
    Eigen::MatrixXd out(PhoneSet::kCount, d);
    for (int p = 0; p < PhoneSet::kCount; ++p) {
        const Eigen::VectorXd fromPrior = featureMean + W.transpose() * (size * m_displacement.row(p).transpose());
        const double n = features.count(p);
        // No weight and no frames of the phone: the person's mean.
        const Eigen::VectorXd mean = kappa + n > 0 ? Eigen::VectorXd((kappa * fromPrior + n * features.mean(p)) / (kappa + n))
                                                   : featureMean;
        out.row(p) = mean.transpose();
    }
    return out;
}

MouthShapePrior MouthShapePrior::load(const std::string &path)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(readWholeFile(path)), &error);
    if (doc.isNull())
        throw Error("not a JSON file (" + error.errorString().toStdString() + ")", path);
    const QJsonObject root = doc.object();
    if (root.value("format").toString() != QLatin1String(kFormat) || root.value("version").toInt() != 1)
        throw Error(std::string("not a mouth prior (format ") + kFormat + ", version 1)", path);
    MouthShapePrior prior;
    prior.m_mean = fromJson(root.value("meanShape"), kPoints, path, "meanShape");
    prior.m_displacement = Eigen::MatrixXd::Zero(PhoneSet::kCount, kPoints);
    prior.m_frames = Eigen::VectorXd::Zero(PhoneSet::kCount);
    const QJsonObject phones = root.value("phones").toObject();
    for (auto it = phones.begin(); it != phones.end(); ++it) {
        const int p = PhoneSet::index(it.key().toStdString());
        if (p < 0)
            throw Error("unknown phone '" + it.key().toStdString() + "'", path);
        const QJsonObject phone = it.value().toObject();
        prior.m_frames(p) = phone.value("frames").toDouble();
        prior.m_displacement.row(p) = fromJson(phone.value("displacement"), kPoints, path, it.key().toStdString()).transpose();
    }
    return prior;
}

void MouthShapePrior::save(const std::string &path) const
{
    QJsonObject phones;
    for (int p = 0; p < PhoneSet::kCount; ++p)
        if (m_frames(p) > 0)
            phones.insert(QString::fromStdString(PhoneSet::label(p)),
                          QJsonObject{{"frames", m_frames(p)}, {"displacement", toJson(m_displacement.row(p).transpose())}});
    const QJsonObject root{{"format", kFormat}, {"version", 1}, {"meanShape", toJson(m_mean)}, {"phones", phones}};
    writeFileAtomically(path, QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString());
}

} // namespace lipsync
