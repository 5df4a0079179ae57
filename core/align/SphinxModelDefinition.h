#pragma once
// The model definition ("mdef") of a CMU Sphinx acoustic model in its binary form (BMDF, what
// Debian's pocketsphinx-en-us ships): the CI phones, every context-dependent phone (base, left
// and right context, word position) and the senone sequence (tied HMM states) of each. Read here
// rather than through libpocketsphinx's bin_mdef, whose structs are not part of the installed
// headers. SphinxAligner looks its triphones up in it.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace lipsync {

class SphinxModelDefinition
{
public:
    // Word positions as the format numbers them (pocketsphinx's word_posn_t).
    enum class Position : int { Internal = 0, Begin = 1, End = 2, Single = 3 };

    // Reads `path` / parses a file's bytes; lipsync::Error naming `fileName` for anything that is
    // not a complete, consistent binary mdef with the same number of states in every phone.
    static SphinxModelDefinition read(const std::string &path);
    static SphinxModelDefinition parse(const std::string &bytes, const std::string &fileName = {});

    int ciPhoneCount() const { return int(m_ciNames.size()); }
    int phoneCount() const { return int(m_sequence.size()); }
    int senoneCount() const { return m_senones; }
    int statesPerPhone() const { return m_states; }
    // The CI phone named `name` ("AA", "SIL", "+NSN+"), or -1.
    int ciPhone(const std::string &name) const;
    const std::string &ciName(int ci) const { return m_ciNames.at(size_t(ci)); }
    int silence() const { return m_silence; }
    // Noise phones (+NSN+, +SPN+, SIL): no triphones of their own; as a context they count as SIL.
    bool isFiller(int ci) const { return m_filler.at(size_t(ci)); }
    // The context-dependent phone of `base` between `left` and `right` (CI phones) at `position`,
    // or -1 when the model has none.
    int triphone(int base, int left, int right, Position position) const;
    // The phone pocketsphinx's dictionary would use (bin_mdef_phone_id_nearest): the triphone,
    // else the same contexts at another word position, else with SIL for filler contexts and for
    // the contexts across the word's edges, else the CI phone `base`.
    int nearestPhone(int base, int left, int right, Position position) const;
    // The senone ids of `phone`'s emitting states (statesPerPhone() of them).
    const uint16_t *senones(int phone) const { return &m_senoneIds.at(size_t(m_sequence.at(size_t(phone))) * size_t(m_states)); }

private:
    std::vector<std::string> m_ciNames;
    std::vector<bool> m_filler;
    std::unordered_map<uint32_t, int> m_triphones; // key(base, left, right, position) -> phone
    std::vector<int> m_sequence;                                // phone -> its senone sequence
    std::vector<uint16_t> m_senoneIds;                          // sequences x states
    int m_states = 0, m_senones = 0, m_silence = -1;
};

} // namespace lipsync
