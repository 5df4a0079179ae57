#include "compare/StudyClipRenderer.h"

#include "aam/AamModel.h"
#include "aam/FaceDetector.h"
#include "dynamics/LabelledFolder.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/VideoReader.h"
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/PostureTransfer.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lipsync::studio {

namespace {

QImage toImage(const cv::Mat &bgr)
{
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return QImage(rgb.data, rgb.cols, rgb.rows, int(rgb.step), QImage::Format_RGB888).copy();
}

} // namespace

StudyClipRenderer::StudyClipRenderer(Project project, bool closeLips)
    : m_project(std::move(project)), m_closeLips(closeLips)
{
}

StudyClipRenderer::~StudyClipRenderer() = default;

std::vector<std::string> StudyClipRenderer::availableMethods(const Project &project)
{
    std::vector<std::string> methods{kRealMethod};
    for (const std::string &kind : dynamicModelKinds())
        if (project.model(kind))
            methods.push_back(kind);
    return methods;
}

std::shared_ptr<const AamModel> StudyClipRenderer::aam()
{
    std::lock_guard lock(m_mutex);
    if (!m_aam) {
        const ModelReference *ref = m_project.aam();
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
        const ModelReference *ref = m_project.model(kind);
        if (!ref)
            throw Error("the project has no trained " + kind + " model", m_project.manifestPath(), "models");
        // The model must speak the parameters of the AAM that synthesises: the file records the
        // AAM by its identifier or (models trained in the studio) by its name in the project.
        const std::string path = m_project.resolve(ref->file);
        std::string recorded;
        std::shared_ptr<const DynamicModel> trained = loadModel(path, {}, &recorded);
        const ModelReference *aamRef = m_project.aam();
        if (!modelFitsAam(recorded, faces->identifier, aamRef ? aamRef->name : std::string()))
            throw Error("the model was trained for AAM '" + recorded + "', not for the project's AAM", path, "aam");
        slot = m_project.study && m_project.study->holdsOutUtterances() ? withoutStudyUtterances(*trained)
                                                                       : trained;
    }
    return slot;
}

std::shared_ptr<const DynamicModel> StudyClipRenderer::withoutStudyUtterances(const DynamicModel &trained) const
{
    // The paper's design: the model retrained, as its file records, on every other sequence, so
    // that a trial shows it generating speech it has not seen. Training is deterministic, so
    // every session of the study sees the same model.
    const std::vector<std::string> &held = m_project.study->utterances();
    std::vector<LabelledSequence> data;
    for (LabelledSequence &s : loadProjectSequences(m_project))
        if (std::find(held.begin(), held.end(), s.name) == held.end())
            data.push_back(std::move(s));
    if (data.empty())
        throw Error("no sequence is left to train the " + trained.kind() + " model on without the study's utterances",
                    m_project.manifestPath(), "study");
    std::unique_ptr<DynamicModel> model = createDynamicModel(trained.kind(), retrainingOptions(trained));
    Feedback quiet;
    model->train(data, quiet);
    return model;
}

std::shared_ptr<const FaceRenderer> StudyClipRenderer::faces(const Sequence &sequence, Feedback &feedback)
{
    {
        std::lock_guard lock(m_mutex);
        if (const auto it = m_faces.find(sequence.id); it != m_faces.end())
            return it->second;
    }
    // The face is tracked in the recording once (core/render/FaceRenderer); both sides of a trial
    // then share its pose, so they differ only in the modelled face.
    const std::shared_ptr<const AamModel> model = aam();
    FaceDetector detector(FaceDetectorPaths::boxesOnly());
    auto renderer = std::make_shared<const FaceRenderer>(*model, m_project.mediaPath(sequence), feedback, &detector);
    std::lock_guard lock(m_mutex);
    return m_faces.emplace(sequence.id, std::move(renderer)).first->second;
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
    std::shared_ptr<const PostureTransfer> posture;
    std::shared_ptr<const FaceRenderer> renderer;
    if (method != kRealMethod) {
        if (sequence->phones.isEmpty())
            throw Error("sequence '" + utterance + "' has no phone alignment to generate from",
                        m_project.manifestPath(), "study");
        const std::shared_ptr<const DynamicModel> dynamics = model(method);
        // Labels on the video's own frame grid, so frame t of the trajectory is frame t of the clip.
        generated = dynamics->generate(frameLabelsFromTier(sequence->phones, reader.clock()));
        if (m_closeLips)
            generated = BilabialClosure::closeOnPhones(*aam(), generated, sequence->phones, reader.clock());
        posture = PostureTransfer::forModel(*dynamics, *aam());
        Feedback tracking(feedback, 0.0, 0.7);
        renderer = faces(*sequence, tracking);
    }
    const double from = method == kRealMethod ? 0.0 : 0.7;
    for (int t = 0; t < frames; ++t) {
        feedback.throwIfCanceled();
        cv::Mat frame = reader.frame(t);
        if (renderer && t < generated.rows()) {
            const Eigen::VectorXd c = generated.row(t).transpose();
            renderer->renderInto(t, posture ? posture->apply(c, renderer->posture(t)) : c, frame);
        }
        clip.frames.push_back(toImage(frame));
        feedback.setProgress(from + (1.0 - from) * double(t + 1) / frames);
    }
    return clip;
}

} // namespace lipsync::studio
