// `lipsync study create` (a blind forced-choice study design, paper section 4) and
// `lipsync study tally` (its results in the form of the paper's Table 1, with sign-test p-values
// and a Bradley-Terry ranking; CSV export).
//
// A project keeps its study in the project (study.json, referenced by the manifest and saved with
// it, see core/project/Project.h); --out / --results write and read a stand-alone study file.
#include "Command.h"

#include "project/ForcedChoiceStudy.h"
#include "eval/StudyTally.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <optional>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

std::vector<std::string> splitList(const QString &text)
{
    std::vector<std::string> out;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        out.push_back(item.trimmed().toStdString());
    return out;
}

QString projectFolder(const Arguments &arguments)
{
    const QString folder = arguments.value(QStringLiteral("project"));
    const QString manifest = QDir(folder).filePath(QString::fromLatin1(Project::kManifestName));
    if (!QFileInfo(manifest).isFile())
        throw Error("not a project folder (no " + std::string(Project::kManifestName) + ")",
                    folder.toStdString());
    return folder;
}

// The study of --results FILE, or the one kept in the project of --project DIR.
ForcedChoiceStudy loadStudy(const Arguments &arguments, QString *source)
{
    if (arguments.has("results")) {
        *source = arguments.value("results");
        return ForcedChoiceStudy::load(source->toStdString());
    }
    const Project project = Project::load(projectFolder(arguments).toStdString());
    *source = QString::fromStdString(project.studyPath());
    if (!project.study)
        throw Error("the project has no study (create one with lipsync study create --project)",
                    project.manifestPath());
    return *project.study;
}

int runCreate(const QStringList &args)
{
    const Arguments arguments(args);
    const QStringList unknown = arguments.unknown(
        {"methods", "utterances", "participants", "seed", "repeats", "out", "project", "json"});
    if (!unknown.isEmpty())
        return fail(QStringLiteral("study create: unknown option %1").arg(unknown.join(' ')), 2);
    if (!arguments.has("methods") || (arguments.has("out") == arguments.has("project"))
        || (arguments.has("out") && !arguments.has("utterances")))
        return fail(QStringLiteral("usage: lipsync study create --methods real,dpds,... "
                                   "[--utterances ID,ID,...] (--out FILE.json | --project DIR) "
                                   "[--participants N] [--seed S] [--repeats R] [--json]"),
                    2);
    bool ok = true;
    const int participants = arguments.value("participants", "0").toInt(&ok);
    bool seedOk = true;
    const quint64 seed = arguments.value("seed", "1").toULongLong(&seedOk);
    bool repeatsOk = true;
    const int repeats = arguments.value("repeats", "1").toInt(&repeatsOk);
    if (!ok || participants < 0 || !seedOk || !repeatsOk)
        return fail(QStringLiteral("study create: --participants, --seed and --repeats take "
                                   "non-negative integers"),
                    2);
    // In a project the utterances are its sequences (all of them unless --utterances names some).
    std::optional<Project> project;
    std::vector<std::string> utterances = splitList(arguments.value("utterances"));
    if (arguments.has("project")) {
        project = Project::load(projectFolder(arguments).toStdString());
        if (!arguments.has("utterances"))
            for (const Sequence &s : project->sequences)
                utterances.push_back(s.id);
        for (const std::string &u : utterances)
            if (!project->sequence(u))
                throw Error("the project has no sequence '" + u + "'", project->manifestPath(),
                            "sequences");
    }
    ForcedChoiceStudy study(splitList(arguments.value("methods")), utterances, seed, repeats);
    for (int p = 1; p <= participants; ++p)
        study.addParticipant(QStringLiteral("P%1").arg(p, 2, 10, QLatin1Char('0')).toStdString());
    QString out = arguments.value("out");
    if (project) {
        project->study = study;
        project->save(); // manifest and study.json, atomically
        out = QString::fromStdString(project->studyPath());
    } else {
        study.save(out.toStdString());
    }
    if (arguments.flag("json"))
        printJson(QJsonObject{{"study", out},
                              {"methods", qint64(study.methods().size())},
                              {"participants", participants},
                              {"trialsPerSession", study.trialsPerSession()}});
    else
        std::printf("%s: %zu methods, %d participants, %d trials each\n", qPrintable(out),
                    study.methods().size(), participants, study.trialsPerSession());
    return 0;
}

void printTable(const StudyTally &tally, double alpha)
{
    std::printf("%-12s %8s %10s %8s  %-12s %12s %12s\n", "A", "prefer A", "undecided", "prefer B", "B",
                "p (sign)", "p (Holm)");
    for (const PairTally &p : tally.pairs)
        std::printf("%-12s %8d %10d %8d  %-12s %12.3g %12.3g\n", tally.methods[size_t(p.a)].c_str(),
                    p.preferA, p.undecided, p.preferB, tally.methods[size_t(p.b)].c_str(), p.pValue,
                    p.holmPValue);
    std::printf("(p (Holm): adjusted for the %zu pairs tested together; the summary uses it)\n",
                tally.pairs.size());
    std::printf("\nBradley-Terry ranking:\n");
    for (size_t r = 0; r < tally.ranking.size(); ++r) {
        const MethodScore &s = tally.ranking[r];
        std::printf("  %zu. %-12s %.4f  (judged real %d, not %d, undecided %d)\n", r + 1,
                    tally.methods[size_t(s.method)].c_str(), s.strength, s.wins, s.losses,
                    s.undecided);
    }
    std::printf("\n%s\n", tally.summary(alpha).c_str());
}

int runTally(const QStringList &args)
{
    const Arguments arguments(args);
    const QStringList unknown =
        arguments.unknown({"results", "project", "json", "csv", "ranking-csv", "alpha"});
    if (!unknown.isEmpty())
        return fail(QStringLiteral("study tally: unknown option %1").arg(unknown.join(' ')), 2);
    if (arguments.has("results") == arguments.has("project")
        || (arguments.has("results") && arguments.value("results").isEmpty())
        || (arguments.has("project") && arguments.value("project").isEmpty()))
        return fail(QStringLiteral("usage: lipsync study tally (--project DIR | --results "
                                   "FILE.json) [--csv PAIRS.csv] [--ranking-csv RANKING.csv] "
                                   "[--alpha 0.05] [--json]"),
                    2);
    bool ok = true;
    const double alpha = arguments.value("alpha", "0.05").toDouble(&ok);
    if (!ok || alpha <= 0 || alpha >= 1)
        return fail(QStringLiteral("study tally: --alpha takes a number in (0, 1)"), 2);

    QString path;
    const ForcedChoiceStudy study = loadStudy(arguments, &path);
    const StudyTally tally = StudyTally::fromStudy(study);
    if (arguments.has("csv"))
        writeFileAtomically(arguments.value("csv").toStdString(), tally.pairsCsv());
    if (arguments.has("ranking-csv"))
        writeFileAtomically(arguments.value("ranking-csv").toStdString(), tally.rankingCsv());

    if (arguments.flag("json")) {
        QJsonObject json = tally.toJson();
        json["study"] = path;
        json["alpha"] = alpha;
        json["summary"] = QString::fromStdString(tally.summary(alpha));
        printJson(json);
    } else {
        std::printf("%s: %d participants, %d answers (%d unanswered)\n\n", qPrintable(path),
                    tally.participants, tally.answered, tally.unanswered);
        printTable(tally, alpha);
    }
    return 0;
}

const CommandRegistration createRegistration{
    QStringLiteral("study create"),
    QStringLiteral("design a blind forced-choice study (every pair twice, sides swapped)"),
    &runCreate};
const CommandRegistration tallyRegistration{
    QStringLiteral("study tally"),
    QStringLiteral("tally a study: Table 1 counts, sign-test p-values, Bradley-Terry ranking"),
    &runTally};

} // namespace
