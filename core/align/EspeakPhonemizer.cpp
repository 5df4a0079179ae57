#include "align/EspeakPhonemizer.h"

#include "util/PhoneSet.h"

#include <espeak-ng/speak_lib.h>

#include <map>
#include <mutex>
#include <sstream>

namespace lipsync {

namespace {

std::mutex &espeakMutex()
{
    static std::mutex mutex;
    return mutex;
}

// espeak-ng English phoneme mnemonics (phsource/ph_english*) -> ARPAbet. Vowels with a
// following r-colouring in British-style phonemes (A@, e@, I@, O@, U@) become vowel + R, which
// is how the CMU dictionary spells them for American English.
const std::map<std::string, std::string> &mnemonicTable()
{
    static const std::map<std::string, std::string> table{
        {"@", "AH"},    {"@2", "AH"},   {"@5", "AH"},   {"@L", "AH L"}, {"@r", "ER"},
        {"3", "ER"},    {"3:", "ER"},   {"a", "AE"},    {"a#", "AH"},   {"aa", "AA"},
        {"A", "AA"},    {"A:", "AA"},   {"A@", "AA R"}, {"A#", "AE"},   {"aI", "AY"},
        {"aI@", "AY ER"}, {"aI3", "AY ER"}, {"aU", "AW"}, {"aU@", "AW ER"}, {"E", "EH"},
        {"E2", "EH"},   {"e", "EY"},    {"e@", "EH R"}, {"eI", "EY"},   {"I", "IH"},
        {"I2", "IH"},   {"I#", "IH"},   {"i", "IY"},    {"i:", "IY"},   {"i@", "IY AH"},
        {"i@3", "IH R"}, {"I@", "IH R"}, {"0", "AA"},   {"O", "AO"},    {"O:", "AO"},
        {"O@", "AO R"}, {"o@", "AO R"}, {"OI", "OY"},   {"oU", "OW"},   {"oU#", "OW"},
        {"o", "OW"},    {"U", "UH"},    {"u:", "UW"},   {"u", "UW"},    {"U@", "UH R"},
        {"V", "AH"},    {"p", "P"},     {"b", "B"},     {"t", "T"},     {"t#", "T"},
        {"t2", "T"},    {"d", "D"},     {"d#", "D"},    {"k", "K"},     {"g", "G"},
        {"f", "F"},     {"v", "V"},     {"T", "TH"},    {"D", "DH"},    {"s", "S"},
        {"z", "Z"},     {"S", "SH"},    {"Z", "ZH"},    {"h", "HH"},    {"tS", "CH"},
        {"dZ", "JH"},   {"m", "M"},     {"n", "N"},     {"N", "NG"},    {"l", "L"},
        {"r", "R"},     {"r-", "R"},    {"j", "Y"},     {"w", "W"},     {"n-", "N"},
        {"l-", "L"},    {"m-", "M"},    {"*", "T"},     {"?", "T"},     {"x", "K"},
        {"W", "W"},     {"C", "HH"},    {"c", "K"},     {"J", "Y"},     {"R", "R"},
    };
    return table;
}

bool initialise()
{
    static const bool ok = [] {
        if (espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, espeakINITIALIZE_DONT_EXIT) < 0)
            return false;
        return espeak_SetVoiceByName("en-us") == EE_OK || espeak_SetVoiceByName("en") == EE_OK;
    }();
    return ok;
}

} // namespace

std::optional<std::string> EspeakPhonemizer::phonemes(const std::string &word)
{
    std::lock_guard lock(espeakMutex());
    if (!initialise())
        return std::nullopt;
    std::string result;
    const void *text = word.c_str();
    // Mnemonic output (bit 1 clear) with '_' between phonemes (bits 8-23).
    const int mode = int('_') << 8;
    while (text) {
        const char *out = espeak_TextToPhonemes(&text, espeakCHARS_UTF8, mode);
        if (!out)
            break;
        if (*out) {
            if (!result.empty())
                result += ' ';
            result += out;
        }
    }
    return result;
}

Pronunciation EspeakPhonemizer::toArpabet(const std::string &espeakPhonemes)
{
    Pronunciation out;
    std::string cleaned;
    for (char c : espeakPhonemes)
        cleaned += (c == ' ') ? '_' : c;
    std::istringstream in(cleaned);
    std::string token;
    while (std::getline(in, token, '_')) {
        // Stress and length marks carry no phone identity.
        std::string t;
        for (char c : token)
            if (c != '\'' && c != ',' && c != '%' && c != '=')
                t += c;
        if (t.empty())
            continue;
        const auto &table = mnemonicTable();
        auto it = table.find(t);
        if (it == table.end() && t.size() > 1 && (t.back() == ':' || t.back() == '#'))
            it = table.find(t.substr(0, t.size() - 1));
        if (it == table.end())
            continue;
        for (const int p : PronunciationDictionary::parse(it->second))
            out.push_back(p);
    }
    return out;
}

std::optional<Pronunciation> EspeakPhonemizer::pronounce(const std::string &word)
{
    const auto ph = phonemes(word);
    if (!ph)
        return std::nullopt;
    Pronunciation p = toArpabet(*ph);
    if (p.empty())
        return std::nullopt;
    return p;
}

} // namespace lipsync
