#pragma once
// Training of the aligner's monophone HMMs on transcribed utterances, as the paper did with HTK:
//   1. flat start (HCompV): every state gets the global mean and variance of all frames; the
//      variance floor is 1% of the global variance;
//   2. embedded re-estimation (HERest): Baum-Welch over whole utterances built from their
//      transcripts with optional silence between words (UtteranceGraph), utterances in parallel;
//   3. mixture splitting (HHEd MU): after each stage every state with enough data doubles its
//      mixture count (the heaviest component split at +-0.2 standard deviations) up to
//      `mixtures`, followed by more re-estimation.
// The total log-likelihood per frame of each iteration is reported through
// Feedback::reportIteration.
#include "align/AcousticModel.h"
#include "align/PronunciationDictionary.h"
#include "align/UtteranceGraph.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

class Feedback;

struct TrainingUtterance
{
    std::string id;                  // for messages ("bbaf2n")
    Eigen::MatrixXf features;        // AcousticModel::features()
    std::vector<std::vector<Pronunciation>> pronunciations; // per word, variants
    // Reference word timings when the transcript has them (GRID .align, a timed .lab, a TextGrid
    // a user corrected): what calibrate() learns the boundary correction from.
    Tier reference{"words", {}};
};

struct TrainerOptions
{
    MfccOptions features;
    CepstralNormalization normalization = CepstralNormalization::Mean;
    // Mixtures per state at each stage. On GRID s1 (bench_speech) 16 mixtures place 91.5% of
    // the held-out inner word boundaries within 40 ms, 8 mixtures 90.8%.
    std::vector<int> mixtureSchedule{1, 2, 4, 8, 16};
    int iterationsPerStage = 6;
    int firstStageIterations = 8; // from the flat start
    double beam = 400.0; // log-domain forward pruning; an utterance that loses every path is retried unpruned (HERest -t 250 150 1000)
    double minimumStateOccupancy = 3.0; // frames; below it a state keeps its parameters
    double minimumMixtureOccupancy = 2.0; // per component to split further (times dimension)
    bool parallel = true;
    int silenceSeedPercent = 15; // quietest frames per utterance that seed the silence model
    // Recordings start and end in silence: making it mandatory in training keeps the flat start
    // from spreading the first and last phones over it (HTK's recipe puts "sil" at both ends of
    // every training transcript). Silence between words stays optional.
    UtteranceGraph::Options graph{0.5, false};
};

struct TrainingReport
{
    std::vector<double> logLikelihoodPerFrame; // one entry per iteration
    std::vector<std::string> failedUtterances;  // transcript does not fit the audio
    int utterances = 0;
    long long frames = 0;
};

// The statistics of the flat start (HCompV): sums and sums of squares of every frame's features,
// apart for the quietest frames of each utterance (which seed silence) and the others.
struct FlatStartStatistics
{
    Eigen::VectorXd sum[2], sumSquares[2]; // [0] speech, [1] the quiet frames
    long long frames[2] = {0, 0};
    void add(const FlatStartStatistics &other);
};

struct Accumulators;

// Training by parts, as HTK's HERest -p does on a cluster: each machine computes the statistics
// of its share of the utterances (flatStartStatistics, then accumulate under the current model),
// the statistics are summed (FlatStartStatistics::add, Accumulators::add) and one step updates
// the model (flatStart, update). The sums make the same model as train()'s loop over all the
// utterances at once (up to the order of floating-point additions).
class AlignerTrainer
{
public:
    // Trains from scratch. Throws lipsync::Error if no utterance is usable; utterances whose
    // transcript cannot fit their audio are listed in the report and skipped.
    static AcousticModel train(const std::vector<TrainingUtterance> &utterances,
                               const TrainerOptions &options, Feedback &feedback,
                               TrainingReport *report = nullptr);

    // A flat-start model from the global statistics of the utterances.
    static AcousticModel flatStart(const std::vector<TrainingUtterance> &utterances,
                                   const TrainerOptions &options);
    static FlatStartStatistics flatStartStatistics(const std::vector<TrainingUtterance> &utterances,
                                                   const TrainerOptions &options);
    // Throws lipsync::Error when the statistics hold fewer than 2 frames.
    static AcousticModel flatStart(const FlatStartStatistics &statistics, const TrainerOptions &options);

    // One Baum-Welch iteration; updates `model` in place and returns the total log-likelihood
    // per frame under the model before the update. Utterances that cannot be aligned are
    // appended to `failed` (ids).
    // `occupancy` (optional) receives the expected frame count of every model state.
    static double reestimate(AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                             const TrainerOptions &options, std::vector<std::string> *failed = nullptr,
                             std::vector<double> *occupancy = nullptr);
    // reestimate() in its two halves: the expected statistics of the utterances under `model`
    // (E-step; utterances that cannot be aligned are appended to `failed`), and the update of the
    // model from statistics summed over any number of parts (M-step; returns the log-likelihood
    // per frame they were collected at). update() throws lipsync::Error for empty statistics or
    // statistics of another model's shape.
    static Accumulators accumulate(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                   const TrainerOptions &options, std::vector<std::string> *failed = nullptr);
    static double update(AcousticModel &model, const Accumulators &statistics, const TrainerOptions &options,
                         std::vector<double> *occupancy = nullptr);

    // The word-boundary correction of `model` (BoundaryCorrection): the utterances with a
    // reference timing are aligned by the model (in parallel) and its boundaries compared with the
    // reference's. Utterances whose transcript does not fit their audio, or whose reference has
    // other words, are left out (counted in the report).
    static BoundaryCorrection calibrate(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                        const BoundaryCorrection::Options &options,
                                        BoundaryCorrectionReport *report = nullptr);

    // Splits the heaviest components of every state until it has `mixtures`, for states whose
    // occupancy allows `minimumPerComponent` frames per component.
    static void splitMixtures(AcousticModel &model, int mixtures, const std::vector<double> &occupancy,
                              double minimumPerComponent);
};

} // namespace lipsync
