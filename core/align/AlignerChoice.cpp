#include "align/AlignerChoice.h"

namespace lipsync {

namespace {

constexpr const char *kSphinx = "sphinx";

} // namespace

bool AlignerChoice::isSphinx() const
{
    return model == kSphinx || model.rfind(std::string(kSphinx) + ":", 0) == 0;
}

void AlignerChoice::useGenericAdapted()
{
    model = kSphinx;
    adapt = true;
}

std::string AlignerChoice::sphinxModelDir() const
{
    const size_t prefix = std::string(kSphinx).size() + 1; // "sphinx:"
    return model.size() > prefix ? model.substr(prefix) : std::string();
}

} // namespace lipsync
