#pragma once
// A starting point learnt from other speakers for a person with little footage: each phone's mouth
// in the pose-free 23-point frame, as a displacement from the speakers' mean shape in face sizes,
// learnt from a project's tracked, aligned sequences (MouthTrack::points). For a new person it is
// carried onto their mean shape (scaled to their face size), into their AAM by a linear map from
// points to parameters fitted on their own frames, and combined with their own per-phone means by
// MAP: a phone seen in n frames moves from the prior's mean towards its own by n / (n + kappa)
// (docs/models.md §5.4).
// The shipped prior (resources/prior/grid-s1.mouthprior) was learnt on 200 GRID s1 clips.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

struct LabelledSequence;
class MouthMeasurer;
struct MouthTrack;
class Project;

class MouthShapePrior
{
public:
    // Prior weight in frames where chooseWeight cannot choose (fewer than two clips; bench
    // BM_CrossSpeakerPrior: 5, 20 and 80 measured; see docs/performance.md, "A starting point from
    // other speakers").
    static constexpr double kDefaultKappa = 80.0;
    // As a weight: choose it by cross-validation on the person's own tracks (chooseWeight); what
    // `train --prior`, `evaluate --realism --prior` and the Models panel take.
    static constexpr double kCrossValidated = -1.0;
    // The weights chooseWeight tries, in frames; 0 is the person's own means.
    static const std::vector<double> &weightCandidates();

    struct WeightChoice
    {
        double kappa = kDefaultKappa;
        std::vector<double> errors; // per candidate: mean squared error per held-out speech frame
        int folds = 0;              // 0: too few tracks to choose; kappa is the default
    };
    // The weight whose per-phone means (personMeans) best predict the person's own speech frames of
    // tracks left out: k-fold by track (k = min(folds, tracks); a random split with a fixed
    // seed), each held-out speech frame's AAM parameters against its phone's mean from the other
    // folds, squared error averaged over all held-out frames. A minute of footage that covers the
    // speech's phones takes little of the prior; seconds of free speech take much
    // (docs/performance.md, "A starting point from other speakers").
    WeightChoice chooseWeight(const std::vector<MouthTrack> &tracks, int folds = 5) const;
    // `kappa`, or chooseWeight(tracks)'s for kCrossValidated.
    double resolvedWeight(const std::vector<MouthTrack> &tracks, double kappa) const
    {
        return kappa == kCrossValidated ? chooseWeight(tracks).kappa : kappa;
    }

    // Learnt from `tracks` (frames whose phone is known). Throws lipsync::Error for no frames.
    static MouthShapePrior learn(const std::vector<MouthTrack> &tracks);
    static MouthShapePrior load(const std::string &path); // errors name the file
    void save(const std::string &path) const;             // atomically

    // Each phone's mean AAM parameters for the person of `tracks` (their points and features),
    // the prior combined with their own frames (41 x d; PhoneSet order). Throws lipsync::Error when
    // the tracks have too few frames to map points to parameters.
    Eigen::MatrixXd personMeans(const std::vector<MouthTrack> &tracks, double kappa = kDefaultKappa) const;
    // What the prior adds to the person's own per-phone means: personMeans(kappa) minus
    // personMeans(0), for DynamicModel::setMeanShift (ModelOptions::meanShift); kCrossValidated
    // takes chooseWeight(tracks)'s.
    Eigen::MatrixXd personShift(const std::vector<MouthTrack> &tracks, double kappa = kDefaultKappa) const;

    const Eigen::VectorXd &meanShape() const { return m_mean; }
    const Eigen::MatrixXd &displacements() const { return m_displacement; } // 41 x 46, face sizes
    const Eigen::VectorXd &frames() const { return m_frames; }              // per phone

private:
    struct PersonPhones;
    // The prior's phones on the face of `tracks` and their own, fitted once (personMeans).
    PersonPhones personPhones(const std::vector<const MouthTrack *> &tracks) const;

    Eigen::VectorXd m_mean;         // 46: the mean pose-free shape
    Eigen::MatrixXd m_displacement; // 41 x 46
    Eigen::VectorXd m_frames;       // 41: frames each phone was learnt from
};

// personShift() for the project's sequences named in `training` (each tracked and aligned), through
// the project's AAM as `measurer` measures it; `used`, when given, receives the weight taken (the
// chosen one for kCrossValidated). Empty (no shift: the model starts from the person's own means
// alone) when that weight is 0. Errors as mouthTrackOfSequence and personMeans.
Eigen::MatrixXd projectPriorShift(const MouthShapePrior &prior, const MouthMeasurer &measurer, const Project &project,
                                  const std::vector<LabelledSequence> &training, double kappa,
                                  double *used = nullptr);

} // namespace lipsync
