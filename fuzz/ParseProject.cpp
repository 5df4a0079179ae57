#include "FuzzParsers.h"

#include "project/ProjectManifest.h"

#include <QByteArray>

namespace lipsync::fuzz {

void parseProjectBytes(const std::string &bytes)
{
    // Feature files are not opened (the folder does not exist; the CSV parser has its own target).
    ProjectManifest::parse(QByteArray::fromStdString(bytes), "fuzz/project.json", "/nonexistent-fuzz",
                           false);
}

} // namespace lipsync::fuzz
