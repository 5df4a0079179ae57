#pragma once
// The parsers of outside data, each taking a file's bytes from memory. Shared by the libFuzzer
// targets (fuzz/fuzz_<name>, one per parser, each linking only its parser's library) and by
// tests/fuzz/tst_fuzzregressions, which replays the inputs that once crashed a parser
// (tests/data/fuzz/regressions/<name>-<defect>.bin).
// Contract under test: a parser returns or throws lipsync::Error — never crashes, never throws
// anything else, never reads out of bounds or allocates without bound.
#include <map>
#include <string>

namespace lipsync::fuzz {

// fuzz/ParseIo.cpp (lipsync_io)
void parseTextGridBytes(const std::string &bytes);
void parseHtkLabelBytes(const std::string &bytes);
void parseGridAlignBytes(const std::string &bytes);
void parseTranscriptBytes(const std::string &bytes);
void parseFeatureCsvBytes(const std::string &bytes);
// fuzz/ParseProject.cpp (lipsync_project)
void parseProjectBytes(const std::string &bytes);
// fuzz/ParseAam.cpp (lipsync_aam)
void parsePtsBytes(const std::string &bytes);
void parseAamBytes(const std::string &bytes);
// fuzz/ParseAligner.cpp (lipsync_align)
void parseAlignerBytes(const std::string &bytes);
void parseTrainingStatisticsBytes(const std::string &bytes); // aligner train --accumulate-only
void parsePhoneBigramBytes(const std::string &bytes);       // live recognition's phone bigram
void parseSphinxMdefBytes(const std::string &bytes);      // CMU Sphinx binary mdef
void parseSphinxGaussiansBytes(const std::string &bytes); // Sphinx-3 means / variances
void parseSphinxSendumpBytes(const std::string &bytes);   // pocketsphinx mixture weights
// fuzz/ParseModelFile.cpp (lipsync_dynamics)
void parseModelFileBytes(const std::string &bytes);

using Parser = void (*)(const std::string &bytes);

// By name: "aam", "aligner", "featurecsv", "gridalign", "htklabel", "modelfile", "phonebigram",
// "project", "pts", "sphinxgauden", "sphinxmdef", "sphinxsendump", "textgrid", "trainingstats", "transcript" (fuzz/FuzzParsers.cpp, links them all).
const std::map<std::string, Parser> &parsers();

} // namespace lipsync::fuzz
