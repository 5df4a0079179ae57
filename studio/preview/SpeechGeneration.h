#pragma once
// Generate from new speech, the work of the preview's task: a media file (any audio or video)
// and its transcript -> forced alignment (the studio's aligner, timeline/AlignTask) -> phone
// labels voted per frame at the chosen frame rate -> the dynamic model's most likely AAM
// trajectory for them (DynamicModel::generate). Runs on a worker thread; the faces are drawn by
// GeneratedFaces on the GUI thread.
#include "project/Tier.h"

#include <QString>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {
class DynamicModel;
class Feedback;
}

namespace lipsync::studio {

struct SpeechRequest
{
    QString mediaPath;
    std::string transcript;
    double frameRate = 25.0;
    QString kind; // of `model`
    std::shared_ptr<const DynamicModel> model;
};

struct SpeechResult
{
    Tier words{"words", {}};
    Tier phones{"phones", {}};
    std::vector<int> labels; // one per frame
    Eigen::MatrixXd params;  // frames x combined AAM modes
    double duration = 0.0;   // seconds of audio
};

// Throws lipsync::Error naming the file (no transcript, unknown words, undecodable audio, an
// untrained model) and Canceled when `feedback` is canceled between the steps.
SpeechResult generateFromSpeech(const SpeechRequest &request, Feedback &feedback);

} // namespace lipsync::studio
