#include "align/SphinxModelDefinition.h"

#include "align/SphinxFileReader.h"
#include "util/Error.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <tuple>

namespace lipsync {

namespace {

uint32_t key(int base, int left, int right, int position)
{
    return ((uint32_t(base) * 256 + uint32_t(left)) * 256 + uint32_t(right)) * 4 + uint32_t(position);
}

} // namespace

SphinxModelDefinition SphinxModelDefinition::read(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read the CMU Sphinx model definition", path);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parse(bytes, path);
}

// The file (sphinxbase's bin_mdef.c, format version 1), all integers in the writer's byte order:
//   "BMDF" (or "FDMB" when written big-endian), int32 version 1, int32 header length, the header
//   (a text description of the format), 10 int32 counts (n_ciphone, n_phone, n_emit_state,
//   n_ci_sen, n_sen, n_tmat, n_sseq, n_ctx, n_cd_tree, sil), the CI phone names (NUL-terminated),
//   padding to a 4-byte boundary, cd_tree[n_cd_tree] {int16 ctx, int16 n_down, int32 pid/down},
//   phones[n_phone] {int32 ssid, int32 tmat, uint8 info[4]} (CI: info[0] = filler; CD: info =
//   word position, base, left, right), then — not in the header's description — an int32 holding
//   n_sseq * n_emit_state, and the senone sequences as uint16[n_sseq][n_emit_state].
SphinxModelDefinition SphinxModelDefinition::parse(const std::string &bytes, const std::string &fileName)
{
    auto fail = [&](const std::string &what) -> Error {
        return Error("invalid CMU Sphinx model definition: " + what, fileName);
    };
    SphinxFileReader r(bytes, fileName, "CMU Sphinx model definition");
    r.need(4, "magic");
    if (bytes.compare(0, 4, "FDMB") == 0)
        r.setSwap(true);
    else if (bytes.compare(0, 4, "BMDF") != 0)
        throw fail(bytes.compare(0, 4, "0.3\n") == 0 ? "a text mdef (convert it with pocketsphinx_mdef_convert -bin)"
                                                     : "not a binary mdef (no BMDF signature)");
    r.skip(4, "magic");
    if (const uint32_t version = r.u32("version"); version != 1)
        throw fail("unsupported format version " + std::to_string(version));
    r.skip(r.u32("header length"), "header");
    uint32_t counts[10];
    for (uint32_t &c : counts)
        c = r.u32("counts");
    const auto [nCi, nPhone, nStates, nCiSen, nSen, nTmat, nSseq, nCtx, nTree, sil] =
        std::tuple{counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6], counts[7], counts[8], counts[9]};
    (void)nCiSen;
    (void)nTmat;
    if (nCi == 0 || nCi > 255) // the CD phones' contexts are bytes
        throw fail("CI phone count " + std::to_string(nCi) + " out of range");
    if (nStates == 0 || nStates > 16)
        throw fail("states per phone " + std::to_string(nStates) + " not supported (heterogeneous or out of range)");
    if (nCtx != 3)
        throw fail("only triphone models are supported (context size " + std::to_string(nCtx) + ")");
    if (sil >= nCi)
        throw fail("the silence phone is out of range");
    if (nSen == 0 || nSen > 65535)
        throw fail("senone count out of range");
    // Each table must fit in what is left before anything is allocated for it.
    if (uint64_t(nPhone) * 12 > r.remaining() || uint64_t(nTree) * 8 > r.remaining() ||
        uint64_t(nSseq) * nStates * 2 > r.remaining() || nPhone < nCi)
        throw fail("table sizes do not fit the file");

    SphinxModelDefinition m;
    m.m_states = int(nStates);
    m.m_senones = int(nSen);
    m.m_silence = int(sil);
    for (uint32_t i = 0; i < nCi; ++i) {
        m.m_ciNames.push_back(r.cstring("CI phone names"));
        if (m.m_ciNames.back().empty())
            throw fail("an empty CI phone name");
    }
    r.skip((4 - r.position() % 4) % 4, "padding");
    r.skip(uint64_t(nTree) * 8, "context tree"); // the phones table below holds the same contexts
    m.m_filler.assign(nCi, false);
    m.m_sequence.resize(nPhone);
    for (uint32_t p = 0; p < nPhone; ++p) {
        const uint32_t ssid = r.u32("phones");
        r.u32("phones"); // transition matrix: the aligner uses none (see SphinxAligner)
        uint8_t info[4];
        for (uint8_t &b : info)
            b = r.u8("phones");
        if (ssid >= nSseq)
            throw fail("phone " + std::to_string(p) + " has senone sequence " + std::to_string(ssid) + " of " + std::to_string(nSseq));
        m.m_sequence[p] = int(ssid);
        if (p < nCi) {
            m.m_filler[p] = info[0] != 0;
            continue;
        }
        if (info[0] > 3 || info[1] >= nCi || info[2] >= nCi || info[3] >= nCi)
            throw fail("triphone " + std::to_string(p) + " has a context out of range");
        m.m_triphones.emplace(key(info[1], info[2], info[3], info[0]), int(p));
    }
    m.m_filler[sil] = true;
    if (r.u32("senone sequences") != uint64_t(nSseq) * nStates)
        throw fail("the senone sequence table size does not match the counts");
    m.m_senoneIds.resize(size_t(nSseq) * nStates);
    for (uint16_t &s : m.m_senoneIds) {
        s = r.u16("senone sequences");
        if (s >= nSen)
            throw fail("senone " + std::to_string(s) + " out of range (" + std::to_string(nSen) + " senones)");
    }
    return m;
}

int SphinxModelDefinition::ciPhone(const std::string &name) const
{
    for (size_t i = 0; i < m_ciNames.size(); ++i)
        if (m_ciNames[i] == name)
            return int(i);
    return -1;
}

int SphinxModelDefinition::nearestPhone(int base, int left, int right, Position position) const
{
    auto anyPosition = [&](int l, int r) {
        if (const int p = triphone(base, l, r, position); p >= 0)
            return p;
        for (int other = 0; other < 4; ++other)
            if (other != int(position))
                if (const int p = triphone(base, l, r, Position(other)); p >= 0)
                    return p;
        return -1;
    };
    if (const int p = anyPosition(left, right); p >= 0)
        return p;
    const bool edgeLeft = position == Position::Begin || position == Position::Single;
    const bool edgeRight = position == Position::End || position == Position::Single;
    const int l = isFiller(left) || edgeLeft ? m_silence : left;
    const int r = isFiller(right) || edgeRight ? m_silence : right;
    if (l != left || r != right)
        if (const int p = anyPosition(l, r); p >= 0)
            return p;
    return base;
}

int SphinxModelDefinition::triphone(int base, int left, int right, Position position) const
{
    if (base < 0 || left < 0 || right < 0 || base >= ciPhoneCount() || left >= ciPhoneCount() || right >= ciPhoneCount())
        return -1;
    const auto it = m_triphones.find(key(base, left, right, int(position)));
    return it == m_triphones.end() ? -1 : it->second;
}

} // namespace lipsync
