#include "FuzzParsers.h"

#include "align/AcousticModel.h"
#include "align/SphinxModelDefinition.h"

namespace lipsync::fuzz {

void parseAlignerBytes(const std::string &bytes) { AcousticModel::parse(bytes, "fuzz.aligner"); }

void parseSphinxMdefBytes(const std::string &bytes) { SphinxModelDefinition::parse(bytes, "fuzz.mdef"); }

} // namespace lipsync::fuzz
