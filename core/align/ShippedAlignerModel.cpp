#include "align/ShippedAlignerModel.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lipsync {

std::string shippedAlignerModelPath(const std::string &sourceDir)
{
    const QString relative = QStringLiteral("resources/aligner/grid-s1.aligner");
    const QString env = qEnvironmentVariable("LIPSYNC_ALIGNER_MODEL");
    if (!env.isEmpty())
        return env.toStdString();
    QDir dir(QCoreApplication::applicationDirPath());
    for (int up = 0; up < 5; ++up) {
        const QString candidate = dir.filePath(relative);
        if (QFileInfo::exists(candidate))
            return QFileInfo(candidate).absoluteFilePath().toStdString();
        if (!dir.cdUp())
            break;
    }
    if (!sourceDir.empty()) {
        const QString candidate = QDir(QString::fromStdString(sourceDir)).filePath(relative);
        if (QFileInfo::exists(candidate))
            return QFileInfo(candidate).absoluteFilePath().toStdString();
    }
    const QString installed =
        QCoreApplication::applicationDirPath() + QStringLiteral("/../share/lipsync/aligner/grid-s1.aligner");
    if (QFileInfo::exists(installed))
        return QFileInfo(installed).absoluteFilePath().toStdString();
    return {};
}

} // namespace lipsync
