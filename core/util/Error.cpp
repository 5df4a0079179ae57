#include "util/Error.h"

namespace lipsync {

namespace {
std::string compose(const std::string &message, const std::string &file, const std::string &field)
{
    std::string text;
    if (!file.empty())
        text += file + ": ";
    if (!field.empty())
        text += field + ": ";
    return text + message;
}
} // namespace

Error::Error(const std::string &message, const std::string &file, const std::string &field)
    : std::runtime_error(compose(message, file, field)), m_file(file), m_field(field),
      m_reason(message)
{
}

} // namespace lipsync
