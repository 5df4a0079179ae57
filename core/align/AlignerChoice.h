#pragma once
// Which forced aligner aligns a speaker's speech (createAligner, align/Aligner.h), as the CLI's
// options, a project (align/ProjectAligner) or a trained model's file (dynamics/ModelFile) say.
#include <string>
#include <tuple>

namespace lipsync {

// Which aligner: `model` is "sphinx" or "sphinx:DIR" (CMU Sphinx's model, at its Debian folder
// or at DIR), the path of an aligner model of ours, or empty for the shipped one
// ($LIPSYNC_ALIGNER_MODEL, else resources/aligner/grid-s1.aligner).
struct AlignerChoice
{
    std::string model;
    bool adapt = false; // adapt the model to the recording's speaker first
    // Our model's word-boundary correction (BoundaryCorrection), when it has one; false: the
    // HMM's own boundaries, as the paper's aligner (the paper preset, docs/models.md §8).
    bool boundaryCorrection = true;
    // Measure AlignerOutput::transcriptFit: a pass over every state for every frame (ours: about
    // a third more time than the alignment itself; CMU Sphinx's: as long again), asked for by
    // `lipsync align` and the studio's alignments.
    bool transcriptFit = false;

    bool isSphinx() const;
    // CMU Sphinx's generic model at Debian's folder, adapted to the recording's speaker: the
    // aligner for a speaker no model of ours knows. The other fields are kept.
    void useGenericAdapted();
    // With isSphinx(): DIR of "sphinx:DIR", empty for "sphinx" (Debian's folder).
    std::string sphinxModelDir() const;
    bool operator<(const AlignerChoice &o) const
    {
        return std::tie(model, adapt, boundaryCorrection, transcriptFit)
               < std::tie(o.model, o.adapt, o.boundaryCorrection, o.transcriptFit);
    }
};

} // namespace lipsync
