#include "align/Aligner.h"

#include "align/MonophoneAligner.h"
#include "align/ShippedAlignerModel.h"
#include "align/SphinxAligner.h"
#include "util/Error.h"

namespace lipsync {

std::unique_ptr<Aligner> createAligner(const AlignerChoice &choice)
{
    if (choice.isSphinx()) {
        SphinxAligner::Options options;
        options.modelDir = choice.sphinxModelDir();
        options.adaptationPasses = choice.adapt ? 1 : 0;
        options.measureTranscriptFit = choice.transcriptFit;
        return std::make_unique<SphinxAligner>(options);
    }
    const std::string path = choice.model.empty() ? shippedAlignerModelPath() : choice.model;
    if (path.empty())
        throw Error("no aligner model given, and the shipped aligner/grid-s1.aligner was not found among the "
                    "resources (set LIPSYNC_ALIGNER_MODEL to a model trained with `lipsync aligner train`)");
    auto aligner = std::make_unique<MonophoneAligner>(path, choice.adapt);
    if (!choice.boundaryCorrection)
        aligner->dropBoundaryCorrection();
    aligner->measureTranscriptFit(choice.transcriptFit);
    return aligner;
}

std::shared_ptr<const Aligner> AlignerCache::get(const AlignerChoice &choice)
{
    const std::lock_guard lock(m_mutex);
    std::shared_ptr<const Aligner> &slot = m_aligners[choice];
    if (!slot) {
        try {
            slot = createAligner(choice);
        } catch (...) {
            m_aligners.erase(choice);
            throw;
        }
    }
    return slot;
}

bool AlignerCache::holds(const AlignerChoice &choice) const
{
    const std::lock_guard lock(m_mutex);
    return m_aligners.count(choice) > 0;
}

} // namespace lipsync
