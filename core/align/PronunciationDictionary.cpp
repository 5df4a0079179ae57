#include "align/PronunciationDictionary.h"

#include "util/Environment.h"
#include "util/PhoneSet.h"
#include "util/Error.h"

#include <cctype>
#include <fstream>
#include <sstream>

namespace lipsync {

std::string PronunciationDictionary::normalizeWord(const std::string &word)
{
    auto keep = [](unsigned char c) { return std::isalnum(c) || c >= 0x80; };
    size_t begin = 0, end = word.size();
    while (begin < end && !keep(static_cast<unsigned char>(word[begin])) && word[begin] != '\'')
        ++begin;
    while (end > begin && !keep(static_cast<unsigned char>(word[end - 1])))
        --end;
    std::string out;
    out.reserve(end - begin);
    for (size_t i = begin; i < end; ++i)
        out += char(std::tolower(static_cast<unsigned char>(word[i])));
    return out;
}

Pronunciation PronunciationDictionary::parse(const std::string &phones)
{
    Pronunciation out;
    std::istringstream in(phones);
    std::string label;
    while (in >> label) {
        const int index = PhoneSet::index(label);
        if (index < 0)
            throw Error("unknown phone '" + label + "'");
        out.push_back(index);
    }
    return out;
}

std::string PronunciationDictionary::toString(const Pronunciation &pronunciation)
{
    std::string out;
    for (int p : pronunciation) {
        if (!out.empty())
            out += ' ';
        out += PhoneSet::label(p);
    }
    return out;
}

PronunciationDictionary PronunciationDictionary::read(const std::string &path)
{
    std::ifstream file(path);
    if (!file) {
        if (path == kCmuDictPath)
            throw Error("CMU pronouncing dictionary not found (install the Debian package "
                        "pocketsphinx-en-us, or set LIPSYNC_CMUDICT)", path);
        throw Error("cannot read the pronouncing dictionary", path);
    }
    PronunciationDictionary dictionary;
    std::string line;
    int lineNumber = 0;
    while (std::getline(file, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.empty() || line[0] == '#' || line.rfind(";;;", 0) == 0)
            continue;
        const size_t space = line.find_first_of(" \t");
        if (space == std::string::npos)
            throw Error("expected 'word phones'", path, "line " + std::to_string(lineNumber));
        std::string word = line.substr(0, space);
        // Variant markers: "word(2)".
        if (word.size() > 3 && word.back() == ')') {
            const size_t open = word.rfind('(');
            if (open != std::string::npos && open > 0)
                word.resize(open);
        }
        // Trailing comments ("# place, ...") in newer cmudict releases.
        std::string phones = line.substr(space + 1);
        if (const size_t hash = phones.find('#'); hash != std::string::npos)
            phones.resize(hash);
        try {
            dictionary.add(word, parse(phones));
        } catch (const Error &e) {
            throw Error(e.reason(), path, "line " + std::to_string(lineNumber));
        }
    }
    if (dictionary.size() == 0)
        throw Error("no entries", path);
    return dictionary;
}

const PronunciationDictionary &PronunciationDictionary::cmu()
{
    static const PronunciationDictionary dictionary = [] {
        const std::string chosen = environment::value("LIPSYNC_CMUDICT");
        return read(chosen.empty() ? kCmuDictPath : chosen);
    }();
    return dictionary;
}

void PronunciationDictionary::add(const std::string &word, const Pronunciation &pronunciation)
{
    if (pronunciation.empty())
        return;
    auto &variants = m_entries[normalizeWord(word)];
    for (const Pronunciation &p : variants)
        if (p == pronunciation)
            return;
    variants.push_back(pronunciation);
}

const std::vector<Pronunciation> *PronunciationDictionary::find(const std::string &word) const
{
    auto it = m_entries.find(normalizeWord(word));
    return it == m_entries.end() ? nullptr : &it->second;
}

} // namespace lipsync
