#include "util/Environment.h"

#include <QString>
#include <QtGlobal>

namespace lipsync::environment {

std::string value(const char *name)
{
    return qEnvironmentVariable(name).toStdString();
}

bool isSet(const char *name)
{
    return qEnvironmentVariableIsSet(name);
}

} // namespace lipsync::environment
