#include "AlignerSupport.h"

#include "align/ShippedAlignerModel.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lipsync::cli {

QString defaultAlignerModel()
{
    return QString::fromStdString(
        shippedAlignerModelPath(qEnvironmentVariable("LIPSYNC_SOURCE_DIR").toStdString()));
}

std::unique_ptr<Lexicon> makeLexicon(const QString &overridesPath,
                                     const std::map<std::string, std::string> &projectPronunciations)
{
    std::map<std::string, std::vector<Pronunciation>> overrides = Lexicon::parseOverrides(projectPronunciations);
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
