#pragma once
// Speaker adaptation at alignment time, as HTK (HERest -u m with a regression-class tree, then
// MAP) and Kaldi's "align, adapt, re-align" do it: the model's Gaussians are moved towards the
// recording being aligned using that recording's own alignment, and the alignment is repeated.
//   1. statistics: the forward-backward pass over the utterance's graph (BaumWelch) gives every
//      mixture component's occupancy and first moment under the current model;
//   2. MLLR mean transform (Leggetter & Woodland 1995): per regression class (silence/noise,
//      vowels, consonants; a class with too few frames shares the global transform) an affine
//      map mu' = A mu + b of the speaker-independent means, block-diagonal over the static,
//      delta and acceleration coefficients, estimated row by row in closed form for diagonal
//      covariances (w_i = G_i^-1 k_i) — every component moves, observed or not;
//   3. MAP (Gauvain & Lee 1994): each component's mean is then pulled to its own data,
//      mu = (tau mu' + sum_t gamma_t o_t) / (tau + sum_t gamma_t);
// repeated `iterations` times, each pass collecting statistics under the last adapted model.
#include "align/AcousticModel.h"
#include "align/AlignerTrainer.h"
#include "align/PronunciationDictionary.h"
#include "align/UtteranceGraph.h"
#include "tasks/Feedback.h"

#include <Eigen/Core>

#include <vector>

namespace lipsync {

struct Accumulators;

struct AdaptationOptions
{
    int iterations = 3;
    double minimumClassFrames = 300; // a regression class with less data uses the global transform
    double mapWeight = 20.0;         // tau of MAP (frames of prior weight); 0 = MLLR only
    double beam = 400.0;
    UtteranceGraph::Options graph;   // as the aligner's
};

struct AdaptationReport
{
    // Log-likelihood per frame of the utterance (forward-backward, all paths) under the model
    // before the first pass and after each pass.
    std::vector<double> logLikelihoodPerFrame;
};

class SpeakerAdaptation
{
public:
    // The model adapted to one utterance (`features` as the model computes them, the words'
    // pronunciations as for ForcedAligner), without the model's word-boundary correction (its
    // own speaker's; `aligner calibrate` learns the adapted speaker's). Throws lipsync::Error if
    // the transcript cannot fit; `feedback` (optional) is checked for cancel before every pass.
    static AcousticModel adapt(const AcousticModel &model, const std::vector<std::vector<Pronunciation>> &pronunciations,
                               const Eigen::MatrixXf &features, const AdaptationOptions &options = {},
                               Feedback &feedback = Feedback::none(), AdaptationReport *report = nullptr);
    // The model adapted to a speaker from several of their recordings at once (more data: each
    // regression class is more likely to get its own transform, MAP moves more components).
    static AcousticModel adapt(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                               const AdaptationOptions &options = {}, Feedback &feedback = Feedback::none(),
                               AdaptationReport *report = nullptr);

    // One adaptation step from statistics collected under any model: MLLR of `speakerIndependent`'s
    // means, then MAP towards the data. Variances, weights and transitions are kept.
    static AcousticModel transform(const AcousticModel &speakerIndependent, const Accumulators &statistics,
                                   const AdaptationOptions &options);

    // Regression class of a phone: 0 silence and breath, 1 vowels, 2 consonants.
    static int regressionClass(int phone);
    static constexpr int kClasses = 3;
};

} // namespace lipsync
