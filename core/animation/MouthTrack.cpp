#include "animation/MouthTrack.h"

#include "aam/LandmarkScheme.h"
#include "align/FrameLabels.h"
#include "project/Project.h"
#include "render/SpeechToFace.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <cmath>

namespace lipsync {

MouthTrack makeMouthTrack(const MouthMeasurer &measurer, const Eigen::MatrixXd &features, const FrameClock &frames,
                          std::vector<int> phones, std::string soundFile)
{
    if (features.rows() != frames.count() || int(phones.size()) != frames.count())
        throw Error("the mouth track has " + std::to_string(features.rows()) + " feature rows and "
                    + std::to_string(phones.size()) + " phone labels for " + std::to_string(frames.count())
                    + " frames");
    if (!features.allFinite())
        throw Error("the face features hold values that are not numbers (NaN or infinite)", soundFile);
    MouthTrack track;
    track.frames = frames;
    track.phones = std::move(phones);
    track.points.resize(features.rows(), 2 * scheme23::kPointCount);
    Eigen::VectorXd shape;
    for (Eigen::Index r = 0; r < features.rows(); ++r) {
        track.measures.push_back(measurer.measure(features.row(r).transpose(), &shape));
        track.points.row(r) = shape.transpose();
    }
    track.features = features;
    track.soundFile = std::move(soundFile);
    return track;
}

MouthTrack mouthTrackOfSequence(const MouthMeasurer &measurer, const Project &project, const Sequence &sequence)
{
    if (sequence.features.rows() == 0)
        throw Error("sequence '" + sequence.id + "' has no face features: track it with the project's AAM first",
                    project.manifestPath());
    if (sequence.phones.intervals.empty())
        throw Error("sequence '" + sequence.id + "' has no phone alignment: align it first", project.manifestPath());
    const FrameClock frames = sequence.clock();
    std::vector<int> phones;
    for (const std::string &label : voteFrameLabels(sequence.phones, frames))
        phones.push_back(PhoneSet::index(label));
    MouthTrack track = makeMouthTrack(measurer, sequence.features, frames, std::move(phones), project.mediaPath(sequence));
    track.sequenceId = sequence.id;
    return track;
}

MouthTrack mouthTrackOfGenerated(const MouthMeasurer &measurer, const SpeechToFaceResult &result)
{
    return makeMouthTrack(measurer, result.features, result.frames, result.labels, result.mediaPath);
}

std::vector<MouthTrack> projectMouthTracks(const MouthMeasurer &measurer, const Project &project)
{
    std::vector<MouthTrack> tracks;
    for (const Sequence &s : project.sequences)
        if (s.features.rows() > 0 && !s.phones.intervals.empty())
            tracks.push_back(mouthTrackOfSequence(measurer, project, s));
    return tracks;
}

MouthMapping projectMouthMapping(const MouthMeasurer &measurer, const Project &project, std::vector<MouthTrack> *tracks)
{
    std::vector<MouthTrack> own = projectMouthTracks(measurer, project);
    MouthMapping mapping = MouthMapping::learn(own);
    mapping.applyUserShapes(project.mouthShapes);
    if (tracks)
        *tracks = std::move(own);
    return mapping;
}

std::pair<MouthMapping, MouthTrack> projectMouthMappingAndTrack(const MouthMeasurer &measurer, const Project &project,
                                                                const Sequence &sequence)
{
    std::vector<MouthTrack> tracks;
    MouthMapping mapping = projectMouthMapping(measurer, project, &tracks);
    for (MouthTrack &track : tracks)
        if (track.sequenceId == sequence.id)
            return {std::move(mapping), std::move(track)};
    return {std::move(mapping), mouthTrackOfSequence(measurer, project, sequence)}; // not learned from: says why
}

std::pair<int, int> nearestFrameOfShape(const std::vector<MouthTrack> &tracks, const MouthMapping &mapping,
                                        MouthShape shape)
{
    std::pair<int, int> best{-1, -1};
    double bestDistance = INFINITY;
    for (size_t t = 0; t < tracks.size(); ++t)
        for (size_t f = 0; f < tracks[t].measures.size(); ++f) {
            const double d = (mapping.cueFeatures(tracks[t].measures[f]) - mapping.shape(shape)).squaredNorm();
            if (d < bestDistance) {
                bestDistance = d;
                best = {int(t), int(f)};
            }
        }
    return best;
}

} // namespace lipsync
