#include "AlignerSupport.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lipsync::cli {

namespace {
const char *const kModelRelative = "resources/aligner/grid-s1.aligner";
}

QString defaultAlignerModel()
{
    const QString env = qEnvironmentVariable("LIPSYNC_ALIGNER_MODEL");
    if (!env.isEmpty())
        return env;
    QDir dir(QCoreApplication::applicationDirPath());
    for (int up = 0; up < 5; ++up) {
        const QString candidate = dir.filePath(QLatin1String(kModelRelative));
        if (QFileInfo::exists(candidate))
            return QFileInfo(candidate).absoluteFilePath();
        if (!dir.cdUp())
            break;
    }
    const QString source = qEnvironmentVariable("LIPSYNC_SOURCE_DIR");
    if (!source.isEmpty() && QFileInfo::exists(QDir(source).filePath(QLatin1String(kModelRelative))))
        return QDir(source).filePath(QLatin1String(kModelRelative));
    const QString installed = QCoreApplication::applicationDirPath()
        + QStringLiteral("/../share/lipsync/aligner/grid-s1.aligner");
    if (QFileInfo::exists(installed))
        return QFileInfo(installed).absoluteFilePath();
    return {};
}

std::unique_ptr<Lexicon> makeLexicon(const QString &overridesPath)
{
    std::map<std::string, std::vector<Pronunciation>> overrides;
    if (!overridesPath.isEmpty()) {
        const PronunciationDictionary user = PronunciationDictionary::read(overridesPath.toStdString());
        for (const auto &[word, variants] : user.entries())
            overrides[word] = variants;
    }
    return std::make_unique<Lexicon>(&PronunciationDictionary::cmu(), overrides);
}

QStringList alignerMediaFilters()
{
    return {QStringLiteral("*.mpg"), QStringLiteral("*.mp4"), QStringLiteral("*.mov"), QStringLiteral("*.avi"),
            QStringLiteral("*.mkv"), QStringLiteral("*.wav"), QStringLiteral("*.flac"), QStringLiteral("*.mp3"),
            QStringLiteral("*.ogg"), QStringLiteral("*.m4a")};
}

} // namespace lipsync::cli
