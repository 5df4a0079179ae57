#include "preview/SpeechGeneration.h"

#include "dynamics/DynamicModel.h"
#include "dynamics/PhoneLabels.h"
#include "tasks/Feedback.h"
#include "timeline/AlignTask.h"
#include "util/Error.h"

#include <QFileInfo>

#include <cmath>

namespace lipsync::studio {

SpeechResult generateFromSpeech(const SpeechRequest &request, Feedback &feedback)
{
    const std::string path = request.mediaPath.toStdString();
    if (!request.model || !request.model->isTrained())
        throw Error("no trained dynamic model to generate with", path);
    if (!(request.frameRate > 0))
        throw Error("the frame rate must be positive", path);
    feedback.setStatus("aligning the transcript");
    feedback.setProgress(0.05);
    const QString id = QFileInfo(request.mediaPath).completeBaseName();
    const TierPair tiers = alignMedia(id, request.mediaPath, request.transcript);
    feedback.throwIfCanceled();

    SpeechResult result;
    result.words = tiers.words;
    result.phones = tiers.phones;
    // The last phone reaches the end of the audio (the aligner stretches it there).
    result.duration = tiers.phones.intervals.empty() ? 0.0 : tiers.phones.intervals.back().end;
    const int frames = std::max(1, int(std::lround(result.duration * request.frameRate)));
    feedback.setStatus("generating the face parameters");
    feedback.setProgress(0.8);
    result.labels = frameLabelsFromTier(tiers.phones, request.frameRate, frames, path);
    result.params = request.model->generate(result.labels);
    feedback.setProgress(1.0);
    return result;
}

} // namespace lipsync::studio
