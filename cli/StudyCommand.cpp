// `lipsync study create` (a blind forced-choice study design, paper section 4) and
// `lipsync study tally` (its results in the form of the paper's Table 1, with sign-test p-values
// and a Bradley-Terry ranking; CSV export).
//
// A project keeps its study in the project (study.json, referenced by the manifest and saved with
// it, see core/project/Project.h); --out / --results write and read a stand-alone study file.
#include "CommandLine.h"

#include "project/ForcedChoiceStudy.h"
#include "eval/StudyTally.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
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

QString projectFolder(const CommandLine &arguments)
{
    const QString folder = arguments.value(QStringLiteral("project"));
    const QString manifest = QDir(folder).filePath(QString::fromLatin1(Project::kManifestName));
    if (!QFileInfo(manifest).isFile())
        throw Error("not a project folder (no " + std::string(Project::kManifestName) + ")",
                    folder.toStdString());
    return folder;
}

// The study of --results FILE, or the one kept in the project of --project DIR.
ForcedChoiceStudy loadStudy(const CommandLine &arguments, QString *source)
{
    if (arguments.isSet("results")) {
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

int runCreate(const CommandLine &arguments)
{
    if (arguments.isSet("out") == arguments.isSet("project"))
        throw UsageError(QStringLiteral("give either --out FILE.json or --project DIR"));
    if (arguments.isSet("out") && !arguments.isSet("utterances"))
        throw UsageError(QStringLiteral("--out needs --utterances"));
    const int participants = arguments.integer("participants", 0);
    const quint64 seed = arguments.unsignedInteger("seed");
    const int repeats = arguments.integer("repeats", 1);
    // In a project the utterances are drawn from its sequences (a fifth, held out of the models'
    // training as in the paper's study) unless --utterances names them; --no-hold-out shows the
    // project's models as trained (on every sequence, unless --utterances names some).
    const bool holdOut = !arguments.isSet("no-hold-out");
    std::optional<Project> project;
    std::vector<std::string> utterances = splitList(arguments.value("utterances"));
    if (arguments.isSet("project")) {
        project = Project::load(projectFolder(arguments).toStdString());
        if (!arguments.isSet("utterances")) {
            std::vector<std::string> pool = ForcedChoiceStudy::candidateUtterances(*project);
            if (pool.empty())
                for (const Sequence &s : project->sequences)
                    pool.push_back(s.id);
            utterances = holdOut ? ForcedChoiceStudy::drawUtterances(
                                       pool, ForcedChoiceStudy::defaultHeldOutCount(int(pool.size())), seed)
                                 : pool;
        }
        for (const std::string &u : utterances)
            if (!project->sequence(u))
                throw Error("the project has no sequence '" + u + "'", project->manifestPath(),
                            "sequences");
        const std::vector<std::string> trainable = ForcedChoiceStudy::candidateUtterances(*project);
        const auto leftToTrain = std::count_if(trainable.begin(), trainable.end(), [&](const std::string &id) {
            return std::find(utterances.begin(), utterances.end(), id) == utterances.end();
        });
        if (holdOut && !trainable.empty() && leftToTrain == 0)
            throw Error("holding out every utterance leaves no sequence to train the models on (name fewer "
                        "with --utterances, or --no-hold-out)",
                        project->manifestPath(), "study");
    }
    if (!holdOut)
        std::fprintf(stderr, "lipsync study create: warning: the models are shown as trained, on these utterances "
                             "too; the paper's study held its sequences out\n");
    ForcedChoiceStudy study(splitList(arguments.value("methods")), utterances, seed, repeats);
    study.setHoldsOutUtterances(holdOut);
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
    if (arguments.isSet("json"))
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
        std::printf("  %zu. %-12s %.4f  (judged real %d, not %d, undecided %d; real in %.0f %%, 95 %% CI %.0f-%.0f %%)\n",
                    r + 1, tally.methods[size_t(s.method)].c_str(), s.strength, s.wins, s.losses, s.undecided,
                    100 * s.realShare, 100 * s.realShareLow, 100 * s.realShareHigh);
    }
    std::printf("\n%s\n", tally.summary(alpha).c_str());
    if (!tally.caution().empty())
        std::printf("%s\n", tally.caution().c_str());
}

int runTally(const CommandLine &arguments)
{
    if (arguments.isSet("results") == arguments.isSet("project"))
        throw UsageError(QStringLiteral("give either --project DIR or --results FILE.json"));
    const double alpha = arguments.number("alpha");
    if (alpha <= 0 || alpha >= 1)
        throw UsageError(QStringLiteral("--alpha takes a number in (0, 1)"));

    QString path;
    const ForcedChoiceStudy study = loadStudy(arguments, &path);
    const StudyTally tally = StudyTally::fromStudy(study);
    if (arguments.isSet("csv"))
        writeFileAtomically(arguments.value("csv").toStdString(), tally.pairsCsv());
    if (arguments.isSet("ranking-csv"))
        writeFileAtomically(arguments.value("ranking-csv").toStdString(), tally.rankingCsv());

    if (arguments.isSet("json")) {
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

// --project DIR: the study kept in a project.
CommandOption studyProjectOption(const QString &description)
{
    return {QStringLiteral("project"), QStringLiteral("DIR"), description};
}

const CommandRegistration createRegistration{
    {QStringLiteral("study create"),
     QStringLiteral("design a blind forced-choice study (every pair twice, sides swapped)"),
     QStringLiteral("Designs a blind forced-choice study (paper section 4): every pair of methods on every "
                    "utterance twice, sides swapped, in an order of its own for each participant. Kept in the "
                    "project (--project) or written as a stand-alone study file (--out)."),
     {{QStringLiteral("methods"), QStringLiteral("M,M,..."), QStringLiteral("the methods compared: real,dpds,..."), {},
       CommandOption::Required},
      {QStringLiteral("utterances"), QStringLiteral("ID,ID,..."),
       QStringLiteral("the utterances shown (default with --project: a fifth of its sequences with features and "
                      "phones, drawn with --seed)")},
      {QStringLiteral("no-hold-out"), {},
       QStringLiteral("show the project's models as trained (default: each retrained without the study's "
                      "utterances, as in the paper)")},
      studyProjectOption(QStringLiteral("keep the study in this project")),
      {QStringLiteral("out"), QStringLiteral("FILE.json"), QStringLiteral("instead of --project: the study file to write")},
      {QStringLiteral("participants"), QStringLiteral("N"), QStringLiteral("participants P01..PN to add"),
       QStringLiteral("0")},
      {QStringLiteral("seed"), QStringLiteral("S"), QStringLiteral("the seed of the trial orders"), QStringLiteral("1")},
      {QStringLiteral("repeats"), QStringLiteral("R"), QStringLiteral("how many times each trial is shown"),
       QStringLiteral("1")}},
     {}},
    &runCreate};
const CommandRegistration tallyRegistration{
    {QStringLiteral("study tally"),
     QStringLiteral("tally a study: Table 1 counts, sign-test p-values, Bradley-Terry ranking"),
     QStringLiteral("Tallies a study's answers in the form of the paper's Table 1, with sign-test p-values (Holm-"
                    "adjusted) and a Bradley-Terry ranking."),
     {studyProjectOption(QStringLiteral("tally the study kept in this project")),
      {QStringLiteral("results"), QStringLiteral("FILE.json"), QStringLiteral("instead of --project: a study file")},
      {QStringLiteral("csv"), QStringLiteral("PAIRS.csv"), QStringLiteral("also write the pairs' counts as CSV")},
      {QStringLiteral("ranking-csv"), QStringLiteral("RANKING.csv"), QStringLiteral("also write the ranking as CSV")},
      {QStringLiteral("alpha"), QStringLiteral("A"), QStringLiteral("the significance level of the summary, in (0, 1)"),
       QStringLiteral("0.05")}},
     {}},
    &runTally};

} // namespace
