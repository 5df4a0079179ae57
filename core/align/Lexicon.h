#pragma once
// Pronunciations of transcript words, in order of precedence: the project's overrides, the CMU
// dictionary, espeak-ng. Noise tokens ("<VOCNOISE>", "[laugh]", "{cough}") are breath/noise
// ("br"); the words "sil", "sp" are silence.
#include "align/PronunciationDictionary.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lipsync {

class Lexicon
{
public:
    enum class Source { Override, Dictionary, Espeak, Noise, None };

    // `dictionary` may be null (overrides and espeak only). Override keys are normalised.
    explicit Lexicon(const PronunciationDictionary *dictionary,
                     const std::map<std::string, std::vector<Pronunciation>> &overrides = {},
                     bool useEspeak = true);

    // All variants of `word` (empty if none) and where they came from.
    std::vector<Pronunciation> pronounce(const std::string &word, Source *source = nullptr) const;

    // Overrides as a project stores them (Project::pronunciations: word -> "PH ON EMES"), for the
    // constructor. Throws lipsync::Error naming the word with a phone outside the phone set.
    static std::map<std::string, std::vector<Pronunciation>> parseOverrides(const std::map<std::string, std::string> &overrides);
    // The words among `words` that only espeak-ng could pronounce (not overridden, not in the
    // dictionary), once each in order of appearance, with espeak's guess: for the user to check.
    std::vector<std::pair<std::string, Pronunciation>> guessed(const std::vector<std::string> &words) const;

    // Splits a transcript into words (whitespace; punctuation trimmed; empty tokens dropped).
    static std::vector<std::string> splitWords(const std::string &transcript);
    // Pronunciations of every word. Throws lipsync::Error naming all words without one.
    std::vector<std::vector<Pronunciation>> pronounceAll(const std::vector<std::string> &words) const;

private:
    const PronunciationDictionary *m_dictionary;
    std::map<std::string, std::vector<Pronunciation>> m_overrides;
    bool m_useEspeak;
};

} // namespace lipsync
