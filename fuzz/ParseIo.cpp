#include "FuzzParsers.h"

#include "io/FeatureCsv.h"
#include "io/GridAlign.h"
#include "io/HtkLabel.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"

namespace lipsync::fuzz {

void parseTextGridBytes(const std::string &bytes) { parseTextGrid(bytes, "fuzz.TextGrid"); }

void parseHtkLabelBytes(const std::string &bytes)
{
    // An MLF starts with its header; anything else is read as a .lab file.
    if (bytes.rfind("#!MLF!#", 0) == 0)
        parseHtkMlf(bytes, "fuzz.mlf");
    else
        parseHtkLabel(bytes, "fuzz.lab");
}

void parseGridAlignBytes(const std::string &bytes) { parseGridAlign(bytes, "fuzz.align"); }

void parseTranscriptBytes(const std::string &bytes)
{
    // The first byte picks the format (readTranscript dispatches on the extension); the rest is
    // the file.
    static const char *const names[] = {"fuzz.align", "fuzz.TextGrid", "fuzz.lab", "fuzz.txt", "fuzz.srt", "fuzz.vtt"};
    if (bytes.empty())
        return;
    parseTranscript(bytes.substr(1), names[static_cast<unsigned char>(bytes[0]) % 6]);
}

void parseFeatureCsvBytes(const std::string &bytes) { parseFeatureCsv(bytes, "fuzz.csv"); }

} // namespace lipsync::fuzz
