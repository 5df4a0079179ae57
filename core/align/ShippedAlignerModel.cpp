#include "align/ShippedAlignerModel.h"

#include "util/Environment.h"
#include "util/ResourceLocator.h"

namespace lipsync {

std::string shippedAlignerModelPath()
{
    if (std::string chosen = environment::value("LIPSYNC_ALIGNER_MODEL"); !chosen.empty())
        return chosen;
    return ResourceLocator::find("aligner/grid-s1.aligner");
}

std::string shippedPhoneBigramPath()
{
    return ResourceLocator::find("aligner/grid-s1.bigram");
}

} // namespace lipsync
