#include "FuzzParsers.h"

namespace lipsync::fuzz {

const std::map<std::string, Parser> &parsers()
{
    static const std::map<std::string, Parser> table{
        {"aam", &parseAamBytes},
        {"aligner", &parseAlignerBytes},
        {"trainingstats", &parseTrainingStatisticsBytes},
        {"featurecsv", &parseFeatureCsvBytes},
        {"gridalign", &parseGridAlignBytes},
        {"htklabel", &parseHtkLabelBytes},
        {"modelfile", &parseModelFileBytes},
        {"phonebigram", &parsePhoneBigramBytes},
        {"project", &parseProjectBytes},
        {"sphinxgauden", &parseSphinxGaussiansBytes},
        {"sphinxmdef", &parseSphinxMdefBytes},
        {"sphinxsendump", &parseSphinxSendumpBytes},
        {"pts", &parsePtsBytes},
        {"textgrid", &parseTextGridBytes},
        {"transcript", &parseTranscriptBytes},
    };
    return table;
}

} // namespace lipsync::fuzz
