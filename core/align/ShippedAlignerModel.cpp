#include "align/ShippedAlignerModel.h"

#include "util/ResourceLocator.h"

#include <QtGlobal>

namespace lipsync {

std::string shippedAlignerModelPath()
{
    if (const QString env = qEnvironmentVariable("LIPSYNC_ALIGNER_MODEL"); !env.isEmpty())
        return env.toStdString();
    return ResourceLocator::find("aligner/grid-s1.aligner");
}

std::string shippedPhoneBigramPath()
{
    return ResourceLocator::find("aligner/grid-s1.bigram");
}

} // namespace lipsync
