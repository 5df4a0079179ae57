#include "compare/StudyClipRenderer.h"

#include "aam/AamModel.h"
#include "aam/AamSynthesizer.h"
#include "aam/FaceDetector.h"
#include "aam/Procrustes.h"
#include "aam/VideoTracking.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lipsync::studio {

// Where the face is in each recorded frame: the similarity from the AAM's normalised frame to
// the image, from tracking the recording with the same AAM.
struct StudyClipRenderer::Poses
{
    std::vector<Similarity> pose;
};

namespace {

QImage toImage(const cv::Mat &bgr)
{
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return QImage(rgb.data, rgb.cols, rgb.rows, int(rgb.step), QImage::Format_RGB888).copy();
}

const ModelReference *findModel(const Project &project, const std::string &kind)
{
    // The latest reference of a kind wins (the models panel keeps one per kind).
    for (auto it = project.models.rbegin(); it != project.models.rend(); ++it)
        if (it->kind == kind)
            return &*it;
    return nullptr;
}

} // namespace

StudyClipRenderer::StudyClipRenderer(Project project) : m_project(std::move(project)) {}

StudyClipRenderer::~StudyClipRenderer() = default;

std::vector<std::string> StudyClipRenderer::availableMethods(const Project &project)
{
    std::vector<std::string> methods{kRealMethod};
    for (const std::string &kind : dynamicModelKinds())
        if (findModel(project, kind))
            methods.push_back(kind);
    return methods;
}

std::shared_ptr<const AamModel> StudyClipRenderer::aam()
{
    std::lock_guard lock(m_mutex);
    if (!m_aam) {
        const ModelReference *ref = findModel(m_project, "aam");
        if (!ref)
            throw Error("the project has no AAM to synthesise faces with", m_project.manifestPath(), "models");
        m_aam = std::make_shared<const AamModel>(AamModel::load(m_project.resolve(ref->file)));
    }
    return m_aam;
}

std::shared_ptr<const DynamicModel> StudyClipRenderer::model(const std::string &kind)
{
    const std::shared_ptr<const AamModel> faces = aam();
    std::lock_guard lock(m_mutex);
    auto &slot = m_models[kind];
    if (!slot) {
        const ModelReference *ref = findModel(m_project, kind);
        if (!ref)
            throw Error("the project has no trained " + kind + " model", m_project.manifestPath(), "models");
        // The model must speak the parameters of the AAM that synthesises: the file records the
        // AAM by its identifier or (models trained in the studio) by its name in the project.
        const std::string path = m_project.resolve(ref->file);
        std::string recorded;
        slot = loadModel(path, {}, &recorded);
        const ModelReference *aamRef = findModel(m_project, "aam");
        if (!recorded.empty() && recorded != faces->identifier && (!aamRef || recorded != aamRef->name))
            throw Error("the model was trained for AAM '" + recorded + "', not for the project's AAM", path, "aam");
    }
    return slot;
}

std::shared_ptr<const StudyClipRenderer::Poses> StudyClipRenderer::poses(const Sequence &sequence,
                                                                         Feedback &feedback)
{
    {
        std::lock_guard lock(m_mutex);
        if (const auto it = m_poses.find(sequence.id); it != m_poses.end())
            return it->second;
    }
    const std::shared_ptr<const AamModel> model = aam();
    FaceDetectorPaths paths;
    paths.useDlib = false;
    FaceDetector detector(paths);
    const VideoTrackingResult tracked =
        trackVideo(*model, m_project.mediaPath(sequence), detector, feedback, sequence.landmarks);
    const AamSynthesizer synthesizer(*model);
    auto poses = std::make_shared<Poses>();
    for (Eigen::Index t = 0; t < tracked.shapes.rows(); ++t)
        poses->pose.push_back(alignSimilarity(synthesizer.shape(tracked.features.row(t).transpose()),
                                              tracked.shapes.row(t).transpose()));
    std::lock_guard lock(m_mutex);
    return m_poses.emplace(sequence.id, std::move(poses)).first->second;
}

StudyClip StudyClipRenderer::render(const std::string &utterance, const std::string &method, Feedback &feedback)
{
    const Sequence *sequence = m_project.sequence(utterance);
    if (!sequence)
        throw Error("the project has no sequence '" + utterance + "'", m_project.manifestPath(), "study");
    StudyClip clip;
    clip.mediaPath = QString::fromStdString(m_project.mediaPath(*sequence));
    VideoReader reader(m_project.mediaPath(*sequence));
    clip.frameRate = reader.frameRate();
    const int frames = reader.frameCount();

    Eigen::MatrixXd generated;
    std::shared_ptr<const Poses> facePoses;
    std::shared_ptr<const AamModel> faceModel;
    if (method != kRealMethod) {
        if (sequence->phones.isEmpty())
            throw Error("sequence '" + utterance + "' has no phone alignment to generate from",
                        m_project.manifestPath(), "study");
        const std::shared_ptr<const DynamicModel> dynamics = model(method);
        // Labels on the video's own frame grid, so frame t of the trajectory is frame t of the clip.
        generated = dynamics->generate(frameLabelsFromTier(sequence->phones, clip.frameRate, frames));
        faceModel = aam();
        Feedback tracking(feedback, 0.0, 0.7);
        facePoses = poses(*sequence, tracking);
    }
    const double from = method == kRealMethod ? 0.0 : 0.7;
    std::unique_ptr<AamSynthesizer> synthesizer;
    if (faceModel)
        synthesizer = std::make_unique<AamSynthesizer>(*faceModel);
    for (int t = 0; t < frames; ++t) {
        feedback.throwIfCanceled();
        cv::Mat frame = reader.frame(t);
        if (synthesizer && t < generated.rows() && t < int(facePoses->pose.size()))
            synthesizer->composite(generated.row(t).transpose(), facePoses->pose[size_t(t)], frame);
        clip.frames.push_back(toImage(frame));
        feedback.setProgress(from + (1.0 - from) * double(t + 1) / frames);
    }
    return clip;
}

} // namespace lipsync::studio
