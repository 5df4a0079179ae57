// `lipsync study create` and `lipsync study tally`, run as a user runs them, on a study whose
// answers reproduce the paper's Table 1 (33 volunteers, every pair twice).
#include "CliRun.h"

#include "project/ForcedChoiceStudy.h"
#include "project/Project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <map>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;
using lipsync::testing::verifyOneLineError;

using namespace lipsync;

namespace {

// 33 participants answer so that the counts are exactly the paper's Table 1.
ForcedChoiceStudy paperStudy()
{
    ForcedChoiceStudy study({"Brand", "DPDS", "reality", "SLDS"}, {"u1", "u2", "u3", "u4"}, 2007);
    for (int p = 0; p < 33; ++p)
        study.addParticipant("V" + std::to_string(p));
    // (a, b) -> answers still to give: prefer a, undecided, prefer b.
    std::map<std::pair<int, int>, std::array<int, 3>> table{{{0, 1}, {5, 7, 54}},  {{0, 2}, {4, 7, 55}},
                                                           {{0, 3}, {36, 21, 9}}, {{1, 2}, {29, 11, 26}},
                                                           {{1, 3}, {60, 5, 1}},  {{2, 3}, {58, 5, 3}}};
    for (int p = 0; p < 33; ++p) {
        for (StudyTrial &t : study.session(p).trials) {
            const int a = std::min(t.left, t.right);
            auto &left = table[{a, std::max(t.left, t.right)}];
            const int kind = left[0] > 0 ? 0 : left[1] > 0 ? 1 : 2;
            --left[size_t(kind)];
            const int chosen = kind == 0 ? a : kind == 2 ? std::max(t.left, t.right) : -1;
            t.choice = chosen < 0 ? StudyChoice::Undecided
                     : chosen == t.left ? StudyChoice::Left : StudyChoice::Right;
        }
    }
    return study;
}

} // namespace

class TestStudyCommand : public QObject
{
    Q_OBJECT

private slots:
    void tallyReproducesTable1()
    {
        QTemporaryDir dir;
        const QString results = dir.filePath("results.json");
        paperStudy().save(results.toStdString());
        const QString csv = dir.filePath("table1.csv");
        const QString rankingCsv = dir.filePath("ranking.csv");
        const Run r = runLipsync({"study", "tally", "--results", results, "--json", "--csv", csv,
                           "--ranking-csv", rankingCsv});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("summary").toString(), QString("DPDS ≈ reality ≻ Brand ≻ SLDS"));
        QCOMPARE(json.value("participants").toInt(), 33);
        QCOMPARE(json.value("answered").toInt(), 33 * 12);
        const QJsonObject first = json.value("pairs").toArray()[0].toObject();
        QCOMPARE(first.value("a").toString(), QString("Brand"));
        QCOMPARE(first.value("preferA").toInt(), 5);
        QCOMPARE(first.value("undecided").toInt(), 7);
        QCOMPARE(first.value("preferB").toInt(), 54);
        QVERIFY(std::abs(first.value("pValue").toDouble() / 1.9067358802971057e-11 - 1) < 1e-9);
        QCOMPARE(json.value("ranking").toArray()[0].toObject().value("method").toString(), QString("DPDS"));

        QFile table(csv);
        QVERIFY(table.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = table.readAll().split('\n');
        QCOMPARE(lines[0], QByteArray("method_a,method_b,prefer_a,undecided,prefer_b,n_decided,p_value,p_holm"));
        QCOMPARE(lines[4], QByteArray("DPDS,reality,29,11,26,55,0.787706,0.787706"));
        QCOMPARE(lines[1], QByteArray("Brand,DPDS,5,7,54,59,1.90674e-11,5.72021e-11"));
        QVERIFY(std::abs(first.value("pValueHolm").toDouble() / (3 * 1.9067358802971057e-11) - 1) < 1e-9);
        QFile ranking(rankingCsv);
        QVERIFY(ranking.open(QIODevice::ReadOnly));
        QVERIFY(ranking.readAll().split('\n')[4].startsWith("4,SLDS,"));

        // Without --json: the table for people.
        const Run text = runLipsync({"study", "tally", "--results", results});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("DPDS ≈ reality ≻ Brand ≻ SLDS"), text.out.constData());
    }

    // In a project the study is part of the project: study.json, referenced by the manifest.
    void createAndTallyInAProject()
    {
        QTemporaryDir dir;
        Project project;
        project.name = "study";
        for (const char *id : {"bbaf2n", "bgin3a", "bwbg8n"})
            project.sequences.push_back(Sequence{id, std::string("media/") + id + ".mpg", 25.0, 75});
        project.save(dir.path().toStdString());
        // By default a fifth of the sequences (at least one), held out of the models' training.
        Run r = runLipsync({"study", "create", "--project", dir.path(), "--methods", "real,dpds", "--seed", "9"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(Project::load(dir.path().toStdString()).study->utterances().size(), size_t(1));
        QVERIFY(Project::load(dir.path().toStdString()).study->holdsOutUtterances());
        // --no-hold-out: every sequence, the project's models as trained, with a warning.
        r = runLipsync({"study", "create", "--project", dir.path(), "--methods", "real,dpds,slds,brand,hmm",
                        "--participants", "4", "--seed", "9", "--no-hold-out", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("warning: the models are shown as trained"), r.err.constData());
        QCOMPARE(parseJsonObject(r.out).value("trialsPerSession").toInt(), 20);
        const Project loaded = Project::load(dir.path().toStdString());
        QVERIFY(loaded.study);
        const ForcedChoiceStudy &study = *loaded.study;
        QCOMPARE(int(study.sessions().size()), 4);
        QCOMPARE(study.sessions()[3].participant, std::string("P04"));
        QCOMPARE(study.utterances(), (std::vector<std::string>{"bbaf2n", "bgin3a", "bwbg8n"}));
        QVERIFY(!study.holdsOutUtterances());

        r = runLipsync({"study", "tally", "--project", dir.path(), "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("answered").toInt(), 0);
        QCOMPARE(json.value("unanswered").toInt(), 80);
        QCOMPARE(json.value("pairs").toArray().size(), 10);

        // Utterances must be sequences of the project.
        verifyOneLineError(runLipsync({"study", "create", "--project", dir.path(), "--methods", "real,dpds",
                                       "--utterances", "nosuch"}),
                           1, "no sequence 'nosuch'");
        QTemporaryDir empty;
        Project().save(empty.path().toStdString());
        verifyOneLineError(runLipsync({"study", "tally", "--project", empty.path()}), 1, "has no study");
    }

    void badInputAndUsage()
    {
        QTemporaryDir dir;
        verifyOneLineError(runLipsync({"study", "tally", "--results", dir.filePath("missing.json")}), 1,
                           "missing.json");
        verifyOneLineError(runLipsync({"study", "tally", "--project", dir.path()}), 1, "not a project folder");
        QFile broken(dir.filePath("broken.json"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\"format\": \"something else\"}");
        broken.close();
        verifyOneLineError(runLipsync({"study", "tally", "--results", dir.filePath("broken.json")}), 1,
                           "broken.json: format:");
        verifyOneLineError(runLipsync({"study", "tally"}), 2, "usage");
        verifyOneLineError(runLipsync({"study", "tally", "--results", "x", "--project", "y"}), 2, "usage");
        verifyOneLineError(runLipsync({"study", "tally", "--results", "x", "--colour"}), 2, "--colour");
        verifyOneLineError(runLipsync({"study", "create", "--methods", "real", "--utterances", "u", "--out",
                                dir.filePath("s.json")}), 1, "at least two methods");
    }
};

QTEST_GUILESS_MAIN(TestStudyCommand)
#include "tst_studycommand.moc"
