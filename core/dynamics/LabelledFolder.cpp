#include "dynamics/LabelledFolder.h"

#include "dynamics/PhoneLabels.h"
#include "io/FeatureCsv.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>

namespace lipsync {

namespace {

std::string formatRate(double rate)
{
    return QString::number(rate, 'g', 10).toStdString();
}

} // namespace

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
        const std::string csvPath = features.filePath(csv).toStdString();
        const FeatureTable table = readFeatureCsv(csvPath);
        LabelledSequence s;
        s.name = name.toStdString();
        s.features = table.values;
        if (s.features.rows() == 0)
            throw Error("no frames", csvPath);
        // Phone times are in seconds: a wrong rate labels every frame wrongly, so no default.
        double rate = table.frameRate;
        if (rate > 0 && fps > 0 && std::abs(rate - fps) > 1e-9 * rate)
            throw Error("records " + formatRate(rate) + " fps, but " + formatRate(fps)
                            + " fps was given (--fps)",
                        csvPath);
        if (rate <= 0)
            rate = fps;
        if (rate <= 0)
            throw Error("records no frame rate (a \"# fps=RATE\" line): give the video's rate "
                        "with --fps",
                        csvPath);
        s.frameRate = rate;
        s.labels = frameLabelsFromTier(readPhoneTier(labelFile.toStdString()), rate,
                                       int(s.features.rows()), labelFile.toStdString());
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<LabelledSequence> loadProjectSequences(const Project &project, std::vector<int> *projectIndex)
{
    std::vector<LabelledSequence> sequences;
    if (projectIndex)
        projectIndex->clear();
    for (size_t i = 0; i < project.sequences.size(); ++i) {
        const Sequence &s = project.sequences[i];
        if (s.features.rows() == 0 || s.phones.isEmpty())
            continue;
        LabelledSequence ls;
        ls.name = s.id;
        ls.features = s.features;
        ls.frameRate = s.frameRate;
        // The frames at their own times (the project records the media's timestamps).
        ls.labels = frameLabelsFromTier(s.phones, s.clock().slice(0, int(s.features.rows())),
                                        project.manifestPath() + ": " + s.id);
        sequences.push_back(std::move(ls));
        if (projectIndex)
            projectIndex->push_back(int(i));
    }
    if (sequences.empty())
        throw Error("no sequence has both face features and a phone alignment "
                    "(track the faces and align the speech first)",
                    project.manifestPath());
    return sequences;
}

} // namespace lipsync
