#include "align/Lexicon.h"

#include "align/EspeakPhonemizer.h"
#include "util/PhoneSet.h"
#include "util/Error.h"

#include <set>
#include <sstream>

namespace lipsync {

Lexicon::Lexicon(const PronunciationDictionary *dictionary,
                 const std::map<std::string, std::vector<Pronunciation>> &overrides, bool useEspeak)
    : m_dictionary(dictionary), m_useEspeak(useEspeak)
{
    for (const auto &[word, variants] : overrides)
        m_overrides[PronunciationDictionary::normalizeWord(word)] = variants;
}

std::vector<Pronunciation> Lexicon::pronounce(const std::string &word, Source *source) const
{
    auto set = [source](Source s) {
        if (source)
            *source = s;
    };
    if (word.size() >= 2) {
        const char open = word.front(), close = word.back();
        if ((open == '<' && close == '>') || (open == '[' && close == ']') || (open == '{' && close == '}')) {
            set(Source::Noise);
            return {Pronunciation{PhoneSet::kBreath}};
        }
    }
    const std::string key = PronunciationDictionary::normalizeWord(word);
    if (key.empty()) {
        set(Source::None);
        return {};
    }
    if (auto it = m_overrides.find(key); it != m_overrides.end() && !it->second.empty()) {
        set(Source::Override);
        return it->second;
    }
    // The pause tokens a transcript may hold. Narrower than PhoneSet::isSilence, which also takes
    // "silence": in a transcript that is a spoken word.
    if (key == PhoneSet::kSilenceLabel || key == "sp") {
        set(Source::Noise);
        return {Pronunciation{PhoneSet::kSilence}};
    }
    if (m_dictionary)
        if (const auto *variants = m_dictionary->find(key)) {
            set(Source::Dictionary);
            return *variants;
        }
    if (m_useEspeak)
        if (auto p = EspeakPhonemizer::pronounce(key)) {
            set(Source::Espeak);
            return {*p};
        }
    set(Source::None);
    return {};
}

std::map<std::string, std::vector<Pronunciation>> Lexicon::parseOverrides(const std::map<std::string, std::string> &overrides)
{
    std::map<std::string, std::vector<Pronunciation>> out;
    for (const auto &[word, phones] : overrides) {
        try {
            out[word] = {PronunciationDictionary::parse(phones)};
        } catch (const Error &e) {
            throw Error("the pronunciation of '" + word + "': " + e.reason());
        }
    }
    return out;
}

std::vector<std::pair<std::string, Pronunciation>> Lexicon::guessed(const std::vector<std::string> &words) const
{
    std::vector<std::pair<std::string, Pronunciation>> out;
    std::set<std::string> seen;
    for (const std::string &w : words) {
        const std::string key = PronunciationDictionary::normalizeWord(w);
        if (!seen.insert(key).second)
            continue;
        Source source = Source::None;
        std::vector<Pronunciation> variants = pronounce(w, &source);
        if (source == Source::Espeak && !variants.empty())
            out.emplace_back(key, variants.front());
    }
    return out;
}

std::vector<std::string> Lexicon::splitWords(const std::string &transcript)
{
    std::vector<std::string> words;
    std::istringstream in(transcript);
    std::string token;
    while (in >> token) {
        const bool noise = token.size() >= 2
            && ((token.front() == '<' && token.back() == '>') || (token.front() == '[' && token.back() == ']')
                || (token.front() == '{' && token.back() == '}'));
        if (noise || !PronunciationDictionary::normalizeWord(token).empty())
            words.push_back(token);
    }
    return words;
}

std::vector<std::vector<Pronunciation>> Lexicon::pronounceAll(const std::vector<std::string> &words) const
{
    std::vector<std::vector<Pronunciation>> out;
    std::string missing;
    for (const std::string &w : words) {
        out.push_back(pronounce(w));
        if (out.back().empty())
            missing += (missing.empty() ? "" : ", ") + w;
    }
    if (!missing.empty())
        throw Error("no pronunciation for: " + missing + " (add them to the project's pronunciations)");
    return out;
}

} // namespace lipsync
