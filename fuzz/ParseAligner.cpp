#include "FuzzParsers.h"

#include "align/AcousticModel.h"
#include "align/PhoneBigram.h"
#include "align/SphinxCodebooks.h"
#include "align/SphinxModelDefinition.h"
#include "align/TrainingStatistics.h"

namespace lipsync::fuzz {

void parseAlignerBytes(const std::string &bytes) { AcousticModel::parse(bytes, "fuzz.aligner"); }

void parsePhoneBigramBytes(const std::string &bytes) { PhoneBigram::parse(bytes, "fuzz.bigram"); }

void parseTrainingStatisticsBytes(const std::string &bytes) { parseTrainingStatistics(bytes, "fuzz.stats"); }

void parseSphinxMdefBytes(const std::string &bytes) { SphinxModelDefinition::parse(bytes, "fuzz.mdef"); }

void parseSphinxGaussiansBytes(const std::string &bytes) { SphinxCodebooks::parseGaussians(bytes, "fuzz.means"); }

// The shape of tests/data/fuzz/sphinxsendump/tiny.sendump (2 streams, 2 codewords, 3 senones).
void parseSphinxSendumpBytes(const std::string &bytes) { SphinxCodebooks::parseMixtureWeights(bytes, "fuzz.sendump", 2, 2, 3); }

} // namespace lipsync::fuzz
