#pragma once
// A pronouncing dictionary: word -> one or more phone-index sequences (PhoneSet indices).
// Reads the CMU dictionary as Debian's pocketsphinx-en-us ships it (lower-case words, ARPAbet
// without stress digits, variants as "word(2)"); stress digits are accepted and dropped.
#include "util/SystemPaths.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace lipsync {

using Pronunciation = std::vector<int>; // PhoneSet indices

class PronunciationDictionary
{
public:
    static constexpr const char *kCmuDictPath = systempaths::kCmuDictionary;

    // Reads a CMU-format dictionary. Throws lipsync::Error naming the file (and line for a bad
    // phone); a missing default file names the Debian package that provides it.
    static PronunciationDictionary read(const std::string &path);
    // The CMU dictionary at kCmuDictPath (or $LIPSYNC_CMUDICT), read once per process.
    static const PronunciationDictionary &cmu();

    void add(const std::string &word, const Pronunciation &pronunciation);
    // Variants in file order, or nullptr. `word` is normalised with normalizeWord().
    const std::vector<Pronunciation> *find(const std::string &word) const;
    size_t size() const { return m_entries.size(); }
    const std::unordered_map<std::string, std::vector<Pronunciation>> &entries() const { return m_entries; }

    // Lower case (ASCII), surrounding punctuation removed, inner apostrophes and hyphens kept.
    static std::string normalizeWord(const std::string &word);
    // Parses "HH AH0 L OW1" (any case, stress digits dropped). Throws lipsync::Error on a label
    // outside the phone set.
    static Pronunciation parse(const std::string &phones);
    static std::string toString(const Pronunciation &pronunciation);

private:
    std::unordered_map<std::string, std::vector<Pronunciation>> m_entries;
};

} // namespace lipsync
