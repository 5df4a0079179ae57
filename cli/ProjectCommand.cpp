// `lipsync project create` (a project from a folder of clips) and `lipsync project check`
// (load and validate a project, report what it holds and which media are missing).
#include "CommandLine.h"

#include "project/Project.h"
#include "util/Error.h"

#include <QFileInfo>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

QJsonObject sequenceSummary(const Project &project, const Sequence &s)
{
    return QJsonObject{{"id", q(s.id)},
                       {"mediaFile", q(s.mediaFile)},
                       {"mediaFound", QFileInfo(q(project.mediaPath(s))).isFile()},
                       {"frameRate", s.frameRate},
                       {"frameCount", s.frameCount},
                       {"duration", s.duration()},
                       {"transcript", q(s.transcript)},
                       {"words", qint64(s.words.intervals.size())},
                       {"phones", qint64(s.phones.intervals.size())},
                       {"landmarkFrames", qint64(s.landmarks.size())},
                       {"featureRows", qint64(s.features.rows())},
                       {"featureColumns", qint64(s.features.cols())}};
}

QJsonObject projectSummary(const Project &project)
{
    QJsonArray sequences;
    QJsonArray missing;
    for (const Sequence &s : project.sequences) {
        sequences.append(sequenceSummary(project, s));
        if (!QFileInfo(q(project.mediaPath(s))).isFile())
            missing.append(q(project.mediaPath(s)));
    }
    QJsonArray models;
    for (const ModelReference &m : project.models)
        models.append(QJsonObject{{"kind", q(m.kind)},
                                  {"name", q(m.name)},
                                  {"file", q(m.file)},
                                  {"found", QFileInfo(q(project.resolve(m.file))).isFile()}});
    return QJsonObject{{"project", q(project.manifestPath())},
                       {"name", q(project.name)},
                       {"formatVersion", Project::kFormatVersion},
                       // Whose aligner the speech is aligned with (Project::aligner; a model of
                       // the project's own wins).
                       {"aligner", project.model("aligner") ? q(project.model("aligner")->name)
                                   : project.alignsGeneric() ? QStringLiteral("generic")
                                                             : QStringLiteral("builtin")},
                       {"sequences", sequences},
                       {"models", models},
                       {"missingMedia", missing}};
}

void printSummary(const Project &project)
{
    int frames = 0;
    for (const Sequence &s : project.sequences)
        frames += s.frameCount;
    std::printf("%s: %zu sequences, %d frames, %zu models\n",
                project.manifestPath().c_str(), project.sequences.size(), frames,
                project.models.size());
    for (const Sequence &s : project.sequences) {
        const bool found = QFileInfo(q(project.mediaPath(s))).isFile();
        std::printf("  %-12s %5d frames @ %6.3f fps  %3zu landmark frames  %s%s\n", s.id.c_str(),
                    s.frameCount, s.frameRate, s.landmarks.size(),
                    s.transcript.empty() ? "(no transcript)" : ("\"" + s.transcript + "\"").c_str(),
                    found ? "" : "  [media not found]");
    }
}

int runCreate(const CommandLine &a)
{
    const std::string out = a.value("out").toStdString();
    if (QFileInfo(q(Project::manifestPath(out))).exists() && !a.isSet("force"))
        return fail(QStringLiteral("%1 already exists; use --force to replace it (the old "
                                   "manifest is kept as project.json.bak)")
                        .arg(q(Project::manifestPath(out))));
    try {
        // A damaged clip is listed and left out; the rest go in.
        std::vector<std::string> skipped;
        const std::string aligner = a.value("aligner").toStdString();
        if (aligner != Project::kBuiltinAligner && aligner != Project::kGenericAligner)
            throw UsageError(QStringLiteral("--aligner: builtin or generic, not '%1'").arg(a.value("aligner")));
        Project project = Project::fromMediaFolder(a.value("media").toStdString(), out, &skipped);
        project.aligner = aligner;
        project.save();
        for (const std::string &why : skipped)
            std::fprintf(stderr, "lipsync project create: skipped %s\n", why.c_str());
        if (a.isSet("json")) {
            QJsonObject summary = projectSummary(project);
            QJsonArray left;
            for (const std::string &why : skipped)
                left.append(QString::fromStdString(why));
            summary[QStringLiteral("skipped")] = left;
            printJson(summary);
        } else {
            printSummary(project);
        }
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

int runCheck(const CommandLine &a)
{
    const QStringList positional = a.positional();
    try {
        // Missing media is reported, not an error: the clips may be on a disk not mounted now.
        const Project project = Project::load(positional[0].toStdString());
        if (a.isSet("json"))
            printJson(projectSummary(project));
        else
            printSummary(project);
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

const CommandRegistration createRegistration{
    {QStringLiteral("project create"),
     QStringLiteral("make a project from a folder of clips (--media DIR --out DIR)"),
     QStringLiteral("Makes a project from a folder of clips: one sequence per clip, with its frames, frame rate "
                    "and the words of a transcript beside it: NAME.align (with word times), NAME.lab, NAME.txt, "
                    "or subtitles NAME.srt / NAME.vtt."),
     {{QStringLiteral("media"), QStringLiteral("DIR"), QStringLiteral("the folder of clips"), {},
       CommandOption::Required},
      {QStringLiteral("out"), QStringLiteral("DIR"), QStringLiteral("the project folder to write"), {},
       CommandOption::Required},
      {QStringLiteral("aligner"), QStringLiteral("builtin|generic"),
       QStringLiteral("whose aligner aligns the project's speech (until the project names one of its own, "
                      "lipsync aligner train/adapt): generic, CMU Sphinx's US-English model adapted to the "
                      "speaker, for anyone; builtin, the shipped model of GRID's speaker s1"),
       QStringLiteral("generic")},
      {QStringLiteral("force"), {},
       QStringLiteral("replace an existing project (the old manifest is kept as project.json.bak)")}},
     {}},
    &runCreate};
const CommandRegistration checkRegistration{
    {QStringLiteral("project check"),
     QStringLiteral("load and validate a project folder, list its sequences"),
     QStringLiteral("Loads and validates a project, lists its sequences and models and reports which media "
                    "files are missing (not an error: the clips may be on a disk not mounted now)."),
     {},
     {{QStringLiteral("DIR"), QStringLiteral("the project folder")}}},
    &runCheck};

} // namespace
