#pragma once
// The one error type of core/: every failure on outside data names the file and, where it applies,
// the field or line, so the studio and the CLI can say exactly what is wrong.
#include <stdexcept>
#include <string>

namespace lipsync {

class Error : public std::runtime_error
{
public:
    explicit Error(const std::string &message, const std::string &file = {},
                   const std::string &field = {});

    const std::string &file() const { return m_file; }
    const std::string &field() const { return m_field; }
    // The bare message, without file and field.
    const std::string &reason() const { return m_reason; }

private:
    std::string m_file;
    std::string m_field;
    std::string m_reason;
};

} // namespace lipsync
