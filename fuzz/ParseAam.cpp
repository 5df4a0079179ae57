#include "FuzzParsers.h"

#include "aam/AamModel.h"
#include "aam/PtsFile.h"

namespace lipsync::fuzz {

void parsePtsBytes(const std::string &bytes) { parsePts(bytes, "fuzz.pts"); }

void parseAamBytes(const std::string &bytes) { AamModel::fromBytes(bytes, "fuzz.aam"); }

} // namespace lipsync::fuzz
