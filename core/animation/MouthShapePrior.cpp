#include "animation/MouthShapePrior.h"

#include "aam/Procrustes.h"
#include "animation/MouthTrack.h"
#include "dynamics/LabelledSequence.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace lipsync {

namespace {

constexpr const char *kFormat = "lipsync-mouth-prior";
constexpr int kPoints = 46;

// The frames of `tracks` whose phone is known, as labelled sequences of their points (or their
// features): what computeFrameStatistics takes the per-phone means (§1) of.
std::vector<LabelledSequence> knownFrames(const std::vector<const MouthTrack *> &tracks, bool points)
{
    std::vector<LabelledSequence> out;
    for (const MouthTrack *track : tracks) {
        const MouthTrack &t = *track;
        std::vector<Eigen::Index> rows;
        LabelledSequence s;
        s.name = t.sequenceId;
        for (int f = 0; f < t.frameCount(); ++f)
            if (const int p = t.phones[size_t(f)]; p >= 0 && p < PhoneSet::kCount) {
                rows.push_back(f);
                s.labels.push_back(p);
            }
        if (rows.empty())
            continue;
        s.features = (points ? t.points : t.features)(rows, Eigen::all);
        out.push_back(std::move(s));
    }
    return out;
}

// Stacked rows of `sequences`, each minus `mean`.
Eigen::MatrixXd centredRows(const std::vector<LabelledSequence> &sequences, const Eigen::VectorXd &mean, long long frames)
{
    Eigen::MatrixXd out(Eigen::Index(frames), mean.size());
    Eigen::Index r = 0;
    for (const LabelledSequence &s : sequences) {
        out.middleRows(r, s.features.rows()) = s.features.rowwise() - mean.transpose();
        r += s.features.rows();
    }
    return out;
}

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

std::vector<const MouthTrack *> pointersTo(const std::vector<MouthTrack> &tracks)
{
    std::vector<const MouthTrack *> out;
    for (const MouthTrack &t : tracks)
        out.push_back(&t);
    return out;
}

} // namespace

// What personMeans combines, fitted once for a person: each phone's mouth from the prior on their
// face, their own mean (the global mean for a phone without frames) and its frames.
struct MouthShapePrior::PersonPhones
{
    Eigen::MatrixXd fromPrior, own; // 41 x d
    Eigen::VectorXd count, globalMean;

    // MAP with a weight of `kappa` frames (41 x d); no weight and no frames: the person's mean.
    Eigen::MatrixXd combined(double kappa) const
    {
        Eigen::MatrixXd out(own.rows(), own.cols());
        for (Eigen::Index p = 0; p < own.rows(); ++p) {
            const double n = count(p);
            out.row(p) = kappa + n > 0 ? Eigen::RowVectorXd((kappa * fromPrior.row(p) + n * own.row(p)) / (kappa + n))
                                       : Eigen::RowVectorXd(globalMean.transpose());
        }
        return out;
    }
};

MouthShapePrior MouthShapePrior::learn(const std::vector<MouthTrack> &tracks)
{
    const std::vector<LabelledSequence> frames = knownFrames(pointersTo(tracks), true);
    if (frames.empty() || frames.front().features.cols() != kPoints)
        throw Error("no tracked, aligned frames to learn mouth shapes from");
    const FrameStatistics points = computeFrameStatistics(frames);
    MouthShapePrior prior;
    prior.m_mean = points.globalMean;
    const double size = shapeSize(prior.m_mean);
    if (!(size > 0))
        throw Error("the tracked frames' mean mouth shape is degenerate");
    prior.m_displacement = Eigen::MatrixXd::Zero(PhoneSet::kCount, kPoints);
    for (int p = 0; p < PhoneSet::kCount; ++p)
        if (points.count(p) > 0)
            prior.m_displacement.row(p) = (points.mean.row(p) - prior.m_mean.transpose()) / size;
    prior.m_frames = points.count.cast<double>();
    return prior;
}

Eigen::MatrixXd MouthShapePrior::personMeans(const std::vector<MouthTrack> &tracks, double kappa) const
{
    return personPhones(pointersTo(tracks)).combined(kappa);
}

MouthShapePrior::PersonPhones MouthShapePrior::personPhones(const std::vector<const MouthTrack *> &tracks) const
{
    const std::vector<LabelledSequence> pointFrames = knownFrames(tracks, true), featureFrames = knownFrames(tracks, false);
    const long long total = std::accumulate(pointFrames.begin(), pointFrames.end(), 0LL,
                                            [](long long n, const LabelledSequence &s) { return n + s.frameCount(); });
    if (total < kPoints || featureFrames.front().features.cols() == 0)
        throw Error("too few tracked, aligned frames to carry the mouth prior to this face (" + std::to_string(total) + ")");
    const FrameStatistics points = computeFrameStatistics(pointFrames), features = computeFrameStatistics(featureFrames);
    const Eigen::Index d = features.mean.cols();
    // Points to parameters on the person's own frames: least squares, centred, lightly regularised.
    const Eigen::MatrixXd X = centredRows(pointFrames, points.globalMean, total);
    const Eigen::MatrixXd Y = centredRows(featureFrames, features.globalMean, total);
    const double ridge = 1e-6 * X.squaredNorm() / double(X.rows());
    const Eigen::MatrixXd W =
        (X.transpose() * X + ridge * Eigen::MatrixXd::Identity(kPoints, kPoints)).ldlt().solve(X.transpose() * Y);
    const double size = shapeSize(points.globalMean);
    PersonPhones out;
    out.fromPrior.resize(PhoneSet::kCount, d);
    for (int p = 0; p < PhoneSet::kCount; ++p)
        out.fromPrior.row(p) = (features.globalMean + W.transpose() * (size * m_displacement.row(p).transpose())).transpose();
    // The person's own means: HMM-mean's (the global mean for a phone without frames).
    out.own = features.mean;
    out.count = features.count.cast<double>();
    out.globalMean = features.globalMean;
    return out;
}

Eigen::MatrixXd MouthShapePrior::personShift(const std::vector<MouthTrack> &tracks, double kappa) const
{
    kappa = resolvedWeight(tracks, kappa);
    const PersonPhones phones = personPhones(pointersTo(tracks));
    return phones.combined(kappa) - phones.combined(0.0);
}

const std::vector<double> &MouthShapePrior::weightCandidates()
{
    static const std::vector<double> candidates{0.0, 5.0, 20.0, 80.0, 320.0};
    return candidates;
}

MouthShapePrior::WeightChoice MouthShapePrior::chooseWeight(const std::vector<MouthTrack> &tracks, int folds) const
{
    WeightChoice choice;
    const int k = std::min(folds, int(tracks.size()));
    if (k < 2)
        return choice;
    std::vector<int> order(tracks.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(2007));
    const std::vector<double> &candidates = weightCandidates();
    std::vector<double> squares(candidates.size(), 0.0);
    long long heldFrames = 0;
    for (int fold = 0; fold < k; ++fold) {
        std::vector<const MouthTrack *> training, held;
        for (size_t i = 0; i < order.size(); ++i)
            (int(i) % k == fold ? held : training).push_back(&tracks[size_t(order[i])]);
        std::vector<Eigen::MatrixXd> means;
        try {
            const PersonPhones phones = personPhones(training);
            for (double kappa : candidates)
                means.push_back(phones.combined(kappa));
        } catch (const Error &) {
            continue; // too few frames left to map points to parameters: this fold says nothing
        }
        for (const MouthTrack *t : held)
            for (int f = 0; f < t->frameCount(); ++f) {
                const int phone = t->phones[size_t(f)];
                if (!PhoneSet::isSpeech(phone) || f >= t->features.rows())
                    continue;
                for (size_t c = 0; c < candidates.size(); ++c)
                    squares[c] += (t->features.row(f) - means[c].row(phone)).squaredNorm();
                ++heldFrames;
            }
        ++choice.folds;
    }
    if (heldFrames == 0) {
        choice.folds = 0;
        return choice;
    }
    for (double &s : squares)
        s /= double(heldFrames);
    choice.errors = squares;
    choice.kappa = candidates[size_t(std::min_element(squares.begin(), squares.end()) - squares.begin())];
    return choice;
}

Eigen::MatrixXd projectPriorShift(const MouthShapePrior &prior, const MouthMeasurer &measurer, const Project &project,
                                  const std::vector<LabelledSequence> &training, double kappa, double *used)
{
    std::vector<MouthTrack> tracks;
    for (const LabelledSequence &t : training)
        if (const Sequence *sequence = project.sequence(t.name))
            tracks.push_back(mouthTrackOfSequence(measurer, project, *sequence));
    kappa = prior.resolvedWeight(tracks, kappa);
    if (used)
        *used = kappa;
    return kappa > 0 ? prior.personShift(tracks, kappa) : Eigen::MatrixXd();
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
