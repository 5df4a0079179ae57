// `lipsync project import DIR [--features DIR] [--alignments DIR] [--aam AAM]`: brings the output
// of `lipsync track` (NAME.csv) and `lipsync align` (NAME.TextGrid) into a project, so a project is
// reproducible from the CLI alone (scripts/make-demo builds the bundled demo this way).
#include "CommandLine.h"

#include "io/FeatureCsv.h"
#include "io/TextGrid.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

// frameCount rows; frames the tracker lost take the nearest tracked frame's features.
Eigen::MatrixXd fillFrames(const FeatureTable &table, int frameCount, const std::string &path)
{
    if (table.frames.empty())
        throw Error("no tracked frames", path);
    Eigen::MatrixXd out(frameCount, table.values.cols());
    std::vector<int> source(size_t(frameCount), -1);
    for (size_t r = 0; r < table.frames.size(); ++r) {
        const int f = table.frames[r];
        if (f < 0 || f >= frameCount)
            throw Error("frame " + std::to_string(f) + " is outside the sequence's "
                            + std::to_string(frameCount) + " frames",
                        path);
        source[size_t(f)] = int(r);
    }
    for (int f = 0; f < frameCount; ++f) {
        int best = -1;
        for (int distance = 0; best < 0 && distance < frameCount; ++distance) {
            if (f - distance >= 0 && source[size_t(f - distance)] >= 0)
                best = source[size_t(f - distance)];
            else if (f + distance < frameCount && source[size_t(f + distance)] >= 0)
                best = source[size_t(f + distance)];
        }
        out.row(f) = table.values.row(best);
    }
    return out;
}

int runImport(const CommandLine &a)
{
    try {
        Project project = Project::load(a.positional()[0].toStdString());
        int features = 0, alignments = 0;
        for (Sequence &s : project.sequences) {
            if (a.isSet("features")) {
                const QString path = QDir(a.value("features")).filePath(q(s.id) + ".csv");
                if (QFileInfo(path).isFile()) {
                    s.features = fillFrames(readFeatureCsv(path.toStdString()), s.frameCount, path.toStdString());
                    ++features;
                }
            }
            if (a.isSet("alignments")) {
                const QString path = QDir(a.value("alignments")).filePath(q(s.id) + ".TextGrid");
                if (QFileInfo(path).isFile()) {
                    const TextGrid grid = readTextGrid(path.toStdString());
                    const Tier *phones = grid.tier("phones");
                    if (!phones)
                        throw Error("no \"phones\" tier", path.toStdString());
                    s.phones = Tier{"phones", phones->intervals};
                    // The words of the import (GRID's .align) stay unless --words asks for the aligner's.
                    if (a.isSet("words")) {
                        if (const Tier *words = grid.tier("words"))
                            s.words = Tier{"words", words->intervals};
                    }
                    ++alignments;
                }
            }
        }
        if (a.isSet("aam")) {
            const QString aam = QDir(q(project.folder())).relativeFilePath(QFileInfo(a.value("aam")).absoluteFilePath());
            ModelReference reference{"aam", a.value("aam-name").toStdString(), aam.toStdString()};
            bool replaced = false;
            for (ModelReference &m : project.models)
                if (m.kind == "aam" && m.file == reference.file) {
                    m = reference;
                    replaced = true;
                }
            if (!replaced)
                project.models.push_back(reference);
        }
        project.save();
        if (a.isSet("json"))
            printJson(QJsonObject{{"project", q(project.manifestPath())},
                                  {"features", features},
                                  {"alignments", alignments},
                                  {"models", qint64(project.models.size())}});
        else
            std::printf("%s: features for %d, alignments for %d of %zu sequences\n",
                        project.manifestPath().c_str(), features, alignments, project.sequences.size());
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

const CommandRegistration registration{
    {QStringLiteral("project import"),
     QStringLiteral("add tracked features (NAME.csv) and alignments (NAME.TextGrid) to a project (DIR --features "
                    "--alignments)"),
     QStringLiteral("Brings the output of `lipsync track` (NAME.csv) and `lipsync align` (NAME.TextGrid) into a "
                    "project, one file per sequence NAME, and references an AAM; frames the tracker lost take "
                    "the nearest tracked frame's features."),
     {{QStringLiteral("features"), QStringLiteral("DIR"), QStringLiteral("a folder of tracked features NAME.csv")},
      {QStringLiteral("alignments"), QStringLiteral("DIR"),
       QStringLiteral("a folder of alignments NAME.TextGrid (their phones tier)")},
      {QStringLiteral("words"), {},
       QStringLiteral("take the alignments' words tier too (default: keep the project's words)")},
      {QStringLiteral("aam"), QStringLiteral("AAM"), QStringLiteral("an AAM file for the project to reference")},
      {QStringLiteral("aam-name"), QStringLiteral("NAME"), QStringLiteral("the name the AAM is shown by"),
       QStringLiteral("AAM")}},
     {{QStringLiteral("DIR"), QStringLiteral("the project folder")}}},
    &runImport};

} // namespace
