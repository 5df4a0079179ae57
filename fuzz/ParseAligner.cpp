#include "FuzzParsers.h"

#include "align/AcousticModel.h"

namespace lipsync::fuzz {

void parseAlignerBytes(const std::string &bytes) { AcousticModel::parse(bytes, "fuzz.aligner"); }

} // namespace lipsync::fuzz
