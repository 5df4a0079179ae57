#include "FuzzParsers.h"

#include "dynamics/ModelFile.h"

namespace lipsync::fuzz {

void parseModelFileBytes(const std::string &bytes) { parseModel(bytes, "fuzz.model"); }

} // namespace lipsync::fuzz
