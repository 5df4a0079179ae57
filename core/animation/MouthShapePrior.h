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
    // Prior weight in frames (bench BM_CrossSpeakerPrior: 5, 20 and 80 measured; see
    // docs/performance.md, "A starting point from other speakers").
    static constexpr double kDefaultKappa = 80.0;

    // Learnt from `tracks` (frames whose phone is known). Throws lipsync::Error for no frames.
    static MouthShapePrior learn(const std::vector<MouthTrack> &tracks);
    static MouthShapePrior load(const std::string &path); // errors name the file
    void save(const std::string &path) const;             // atomically

    // Each phone's mean AAM parameters for the person of `tracks` (their points and features),
    // the prior combined with their own frames (41 x d; PhoneSet order). Throws lipsync::Error when
    // the tracks have too few frames to map points to parameters.
    Eigen::MatrixXd personMeans(const std::vector<MouthTrack> &tracks, double kappa = kDefaultKappa) const;
    // What the prior adds to the person's own per-phone means: personMeans(kappa) minus
    // personMeans(0), for DynamicModel::setMeanShift (ModelOptions::meanShift).
    Eigen::MatrixXd personShift(const std::vector<MouthTrack> &tracks, double kappa = kDefaultKappa) const;

    const Eigen::VectorXd &meanShape() const { return m_mean; }
    const Eigen::MatrixXd &displacements() const { return m_displacement; } // 41 x 46, face sizes
    const Eigen::VectorXd &frames() const { return m_frames; }              // per phone

private:
    Eigen::VectorXd m_mean;         // 46: the mean pose-free shape
    Eigen::MatrixXd m_displacement; // 41 x 46
    Eigen::VectorXd m_frames;       // 41: frames each phone was learnt from
};

// personShift() for the project's sequences named in `training` (each tracked and aligned), through
// the project's AAM as `measurer` measures it. Errors as mouthTrackOfSequence and personMeans.
Eigen::MatrixXd projectPriorShift(const MouthShapePrior &prior, const MouthMeasurer &measurer, const Project &project,
                                  const std::vector<LabelledSequence> &training, double kappa);

} // namespace lipsync
