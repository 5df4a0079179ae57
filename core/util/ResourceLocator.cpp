#include "util/ResourceLocator.h"

#include "util/Environment.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lipsync {

std::string ResourceLocator::executableFolder()
{
    // QCoreApplication knows it once an application object exists; /proc/self/exe always.
    if (QCoreApplication::instance())
        return QCoreApplication::applicationDirPath().toStdString();
    return QFileInfo(QFileInfo(QStringLiteral("/proc/self/exe")).symLinkTarget()).absolutePath().toStdString();
}

std::vector<std::string> ResourceLocator::folders()
{
    std::vector<std::string> out;
    if (const std::string chosen = environment::value("LIPSYNC_RESOURCE_DIR"); !chosen.empty())
        out.push_back(QDir::cleanPath(QFileInfo(QString::fromStdString(chosen)).absoluteFilePath()).toStdString());
    out.push_back(
        QDir::cleanPath(QString::fromStdString(executableFolder()) + QStringLiteral("/../share/lipsync")).toStdString());
    return out;
}

std::string ResourceLocator::find(const std::string &relative)
{
    for (const std::string &folder : folders()) {
        const QFileInfo candidate(QDir(QString::fromStdString(folder)).filePath(QString::fromStdString(relative)));
        if (candidate.exists())
            return QDir::cleanPath(candidate.absoluteFilePath()).toStdString();
    }
    return {};
}

} // namespace lipsync
