#pragma once
// Bounds-checked reading of CMU Sphinx's binary model files from memory (SphinxModelDefinition's
// mdef, SphinxCodebooks' means, variances and sendump): little- or big-endian integers and
// floats, NUL-terminated strings and text lines; anything short of the data throws
// lipsync::Error "truncated <kind> (<what>)" naming the file.
#include "util/Error.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace lipsync {

class SphinxFileReader
{
public:
    // `bytes`, `file` and `kind` ("CMU Sphinx model definition") must outlive the reader.
    SphinxFileReader(const std::string &bytes, const std::string &file, const char *kind)
        : m_bytes(bytes), m_file(file), m_kind(kind)
    {
    }

    void need(uint64_t n, const char *what) const
    {
        if (n > m_bytes.size() - m_at)
            throw Error(std::string("truncated ") + m_kind + " (" + what + ")", m_file);
    }
    void setSwap(bool swap) { m_swap = swap; }
    uint32_t u32(const char *what)
    {
        need(4, what);
        unsigned char b[4];
        std::memcpy(b, m_bytes.data() + m_at, 4);
        m_at += 4;
        return m_swap ? uint32_t(b[3]) | uint32_t(b[2]) << 8 | uint32_t(b[1]) << 16 | uint32_t(b[0]) << 24
                      : uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
    }
    int32_t i32(const char *what) { return int32_t(u32(what)); }
    float f32(const char *what)
    {
        const uint32_t bits = u32(what);
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
    }
    uint16_t u16(const char *what)
    {
        need(2, what);
        const auto b0 = uint16_t(uint8_t(m_bytes[m_at])), b1 = uint16_t(uint8_t(m_bytes[m_at + 1]));
        m_at += 2;
        return m_swap ? uint16_t(b0 << 8 | b1) : uint16_t(b1 << 8 | b0);
    }
    uint8_t u8(const char *what)
    {
        need(1, what);
        return uint8_t(m_bytes[m_at++]);
    }
    std::string cstring(const char *what) { return until('\0', what); }
    // The text up to the next newline (not included).
    std::string line(const char *what) { return until('\n', what); }
    void skip(uint64_t n, const char *what)
    {
        need(n, what);
        m_at += size_t(n);
    }
    size_t position() const { return m_at; }
    size_t remaining() const { return m_bytes.size() - m_at; }

private:
    std::string until(char end, const char *what)
    {
        const size_t at = m_bytes.find(end, m_at);
        if (at == std::string::npos)
            throw Error(std::string("truncated ") + m_kind + " (" + what + ")", m_file);
        std::string s = m_bytes.substr(m_at, at - m_at);
        m_at = at + 1;
        return s;
    }

    const std::string &m_bytes;
    const std::string &m_file;
    const char *m_kind;
    size_t m_at = 0;
    bool m_swap = false;
};

} // namespace lipsync
