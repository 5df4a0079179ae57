#include "dynamics/LabelledFolder.h"

#include "dynamics/PhoneLabels.h"
#include "io/FeatureCsv.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

namespace lipsync {

std::vector<LabelledSequence> loadLabelledFolder(const std::string &featuresDir,
                                                 const std::string &labelsDir, double fps)
{
    const QDir features(QString::fromStdString(featuresDir));
    const QDir labels(QString::fromStdString(labelsDir));
    if (!features.exists())
        throw Error("no such folder", featuresDir);
    if (!labels.exists())
        throw Error("no such folder", labelsDir);
    const QStringList csvFiles = features.entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name);
    if (csvFiles.isEmpty())
        throw Error("no feature files (NAME.csv)", featuresDir);
    std::vector<LabelledSequence> out;
    for (const QString &csv : csvFiles) {
        const QString name = QFileInfo(csv).completeBaseName();
        QString labelFile;
        for (const QString &extension : {QStringLiteral(".TextGrid"), QStringLiteral(".textgrid"),
                                         QStringLiteral(".lab")})
            if (labels.exists(name + extension)) {
                labelFile = labels.filePath(name + extension);
                break;
            }
        if (labelFile.isEmpty())
            throw Error("no " + name.toStdString() + ".TextGrid or " + name.toStdString()
                            + ".lab for the features of " + name.toStdString(),
                        labelsDir);
        const FeatureTable table = readFeatureCsv(features.filePath(csv).toStdString());
        LabelledSequence s;
        s.name = name.toStdString();
        s.features = table.values;
        if (s.features.rows() == 0)
            throw Error("no frames", features.filePath(csv).toStdString());
        s.labels = frameLabelsFromTier(readPhoneTier(labelFile.toStdString()), fps,
                                       int(s.features.rows()), labelFile.toStdString());
        out.push_back(std::move(s));
    }
    return out;
}

} // namespace lipsync
