#pragma once
// The videos of the blind study (paper §4): for an utterance and a method, the frames a
// participant sees. "real" is the recorded video; any other method is a trained dynamic model
// of the project (its kind: "dpds", "slds", "brand", "hmm"), whose trajectory for the
// utterance's frame labels (docs/models.md §0 voting) is synthesised with the project's AAM and
// composited into the recorded frames at the face's tracked pose — so both sides of a trial
// show the same person, background and head motion, and differ only in the modelled face. The
// lips close on /p b m/ (render/BilabialClosure) as in the studio's preview, unless turned off.
// When the study holds its utterances out (the default), each model is first retrained without
// them, so that viewers judge speech it has not seen.
//
// Thread-safe: render() runs in worker tasks; the AAM, the models and the per-utterance face renderers (the tracked poses)
// are loaded or tracked once and shared.
#include "project/Project.h"

#include <QImage>
#include <QString>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lipsync {
class AamModel;
class DynamicModel;
class Feedback;
class FaceRenderer;
} // namespace lipsync

namespace lipsync::studio {

struct StudyClip
{
    std::vector<QImage> frames;
    double frameRate = 25.0;
    QString mediaPath; // the recording: its sound is played with either side
};

class StudyClipRenderer
{
public:
    static constexpr const char *kRealMethod = "real";

    explicit StudyClipRenderer(Project project, bool closeLips = true);
    ~StudyClipRenderer();

    // Throws lipsync::Error naming the file for unreadable media, a missing AAM or model, or an
    // utterance without features or phones; Canceled when `feedback` is canceled.
    StudyClip render(const std::string &utterance, const std::string &method, Feedback &feedback);

    // The methods a study can compare in `project`: "real" and each trained dynamic model kind.
    static std::vector<std::string> availableMethods(const Project &project);

private:
    std::shared_ptr<const AamModel> aam();
    std::shared_ptr<const DynamicModel> model(const std::string &kind);
    // `trained` retrained without the study's utterances (ForcedChoiceStudy::holdsOutUtterances).
    std::shared_ptr<const DynamicModel> withoutStudyUtterances(const DynamicModel &trained) const;
    std::shared_ptr<const FaceRenderer> faces(const Sequence &sequence, Feedback &feedback);

    const Project m_project;
    const bool m_closeLips;
    std::mutex m_mutex;
    std::shared_ptr<const AamModel> m_aam;
    std::map<std::string, std::shared_ptr<const DynamicModel>> m_models;
    // After m_aam: each renderer refers to it.
    std::map<std::string, std::shared_ptr<const FaceRenderer>> m_faces;
};

} // namespace lipsync::studio
