#pragma once
// Our aligner (Aligner): the speaker's monophone HMMs (AcousticModel, `lipsync aligner train`)
// and ForcedAligner's Viterbi over the transcript, on the model's own features of the decoded
// audio. With adaptation the model is first moved to the recording's speaker (SpeakerAdaptation:
// MLLR then MAP of the means, as HTK and Kaldi do). A recording longer than three minutes is
// aligned window by window in bounded memory (LongAlignment). Re-alignment is one constrained Viterbi over
// the whole recording with every kept boundary fixed (Realignment::run).
#include "align/AcousticModel.h"
#include "align/Aligner.h"

namespace lipsync {

// AlignerOutput::transcriptFit of `alignment` (the forced path through `features`).
double transcriptFit(const AcousticModel &model, const Eigen::MatrixXf &features, const AlignmentResult &alignment);

class MonophoneAligner : public Aligner
{
public:
    // `path`: the model file (named in the errors of loading it).
    MonophoneAligner(const std::string &path, bool adapt);

    // Aligns with the HMM's own word boundaries: the model's learned correction is not applied.
    void dropBoundaryCorrection() { m_model.setBoundaryCorrection({}); }
    // Fill AlignerOutput::transcriptFit (AlignerChoice::transcriptFit).
    void measureTranscriptFit(bool on) { m_measureFit = on; }

    std::string name() const override { return m_path; }
    const AcousticModel *acousticModel() const override { return &m_model; }
    using Aligner::align;
    AlignerOutput align(const RecordingSound &sound, const std::vector<std::string> &words, const Lexicon &lexicon,
                        Feedback &feedback = Feedback::none(), const std::string &transcriptPath = {}) const override;
    AlignerOutput realign(const std::string &mediaPath, const Realignment &realignment, const Lexicon &lexicon,
                          Feedback &feedback = Feedback::none()) const override;

private:
    // Recordings longer than kLongRecordingSeconds (`seconds` of sound): window by window
    // (LongAlignment), without adaptation; longer than kMaxRecordingSeconds: refused.
    AlignerOutput alignLong(const RecordingSound &sound, double seconds, const std::vector<std::string> &words,
                            const Lexicon &lexicon, Feedback &feedback, const std::string &transcriptPath) const;

    std::string m_path;
    AcousticModel m_model;
    bool m_adapt = false;
    bool m_measureFit = false;
};

} // namespace lipsync
