// lipsync train / generate / evaluate as users run them, on a tiny synthetic data set (features
// sampled from a DPDS, phone labels as .lab files) plus one real MFA phone alignment (TextGrid).
#include "CliRun.h"

#include "../core/dynamics/SyntheticDynamics.h"

#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/FeatureCsv.h"
#include "project/Project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QMap>
#include <QTest>

#include <cmath>
#include <fstream>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

using namespace lipsync;

namespace {

// .lab from per-frame labels at `fps`: one segment per run.
void writeLab(const std::string &path, const std::vector<int> &labels, double fps = 25.0)
{
    std::ofstream out(path);
    out.precision(17);
    size_t start = 0;
    for (size_t t = 1; t <= labels.size(); ++t)
        if (t == labels.size() || labels[t] != labels[start]) {
            out << double(start) / fps << " " << double(t) / fps << " " << PhoneSet::label(labels[start]) << "\n";
            start = t;
        }
}

} // namespace

class TestDynamicsCli : public QObject
{
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_features, m_labels;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_features = m_dir.filePath(QStringLiteral("features"));
        m_labels = m_dir.filePath(QStringLiteral("labels"));
        QDir().mkpath(m_features);
        QDir().mkpath(m_labels);
        std::mt19937 rng(7);
        const test::DpdsTruth truth = test::randomDpdsTruth(rng, 4, 0.05);
        const std::vector<int> states{PhoneSet::index("B"), PhoneSet::index("IH"), PhoneSet::index("N"),
                                      PhoneSet::index("AA"), PhoneSet::index("T")};
        for (int s = 0; s < 12; ++s) {
            const std::string name = "clip" + std::to_string(s);
            const auto seq = test::sampleDpds(rng, truth, test::randomLabels(rng, 75, states), name);
            writeFeatureCsv((m_features + "/" + QString::fromStdString(name) + ".csv").toStdString(), seq.features,
                            {}, 25.0);
            writeLab((m_labels + "/" + QString::fromStdString(name) + ".lab").toStdString(), seq.labels);
        }
        // One real phone alignment (MFA, short TextGrid form) with synthetic features.
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/dynamics/acoustic_corpus.TextGrid"),
                            m_labels + "/real.TextGrid"));
        const std::vector<int> realLabels =
            frameLabelsFromTier(readPhoneTier((m_labels + "/real.TextGrid").toStdString()), 25.0, 668);
        writeFeatureCsv((m_features + "/real.csv").toStdString(),
                        test::sampleDpds(rng, truth, realLabels, "real").features, {}, 25.0);
    }

    void trainsEveryKind_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<bool>("context");
        for (const char *k : {"dpds", "slds", "brand", "hmm"}) {
            QTest::newRow(k) << QString::fromLatin1(k) << false;
            QTest::newRow((std::string(k) + " in context").c_str()) << QString::fromLatin1(k) << true;
        }
    }
    void trainsEveryKind()
    {
        QFETCH(QString, kind);
        QFETCH(bool, context);
        const QString model = m_dir.filePath(kind + (context ? "-context" : "") + ".json");
        QStringList train{"train", "--kind", kind, "--features", m_features, "--labels", m_labels,
                          "--out", model, "--aam", "aam-test", "--json"};
        if (context)
            train << "--context-states" << "--min-occupancy" << "20" << "--mdl-weight" << "0.5";
        const Run r = runLipsync(train);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value("kind").toString(), kind);
        // Phones in context split some phone of these 13 sequences (docs/models.md §5.2).
        QVERIFY(context ? o.value("states").toInt() > 41 : o.value("states").toInt() == 41);
        QCOMPARE(o.value("sequences").toInt(), 13);
        QCOMPARE(o.value("frames").toInt(), 12 * 75 + 668);
        QCOMPARE(o.value("dimension").toInt(), 4);
        QVERIFY(std::isfinite(o.value("loglikPerFrame").toDouble()));
        QVERIFY(QFile::exists(model));

        // Generate from the real TextGrid: 26.72 s at 25 fps = 669 frames.
        const QString out = m_dir.filePath(kind + "-gen.csv");
        Run g = runLipsync({"generate", "--model", model, "--labels", m_labels + "/real.TextGrid", "--out", out,
                            "--aam", "aam-test", "--json"});
        QVERIFY2(g.exitCode == 0, g.err.constData());
        const FeatureTable table = readFeatureCsv(out.toStdString());
        QCOMPARE(table.values.rows(), Eigen::Index(669));
        QCOMPARE(table.values.cols(), Eigen::Index(4));
        // The frame-by-frame generator writes the same file (Brand: within its fixed-lag error, a
        // few percent of the trajectory's spread).
        const QString streamed = m_dir.filePath(kind + "-stream.csv");
        g = runLipsync({"generate", "--model", model, "--labels", m_labels + "/real.TextGrid", "--out",
                        streamed, "--stream"});
        QVERIFY2(g.exitCode == 0, g.err.constData());
        const Eigen::MatrixXd difference = readFeatureCsv(streamed.toStdString()).values - table.values;
        if (kind == "brand") {
            const double spread = (table.values.rowwise() - table.values.colwise().mean()).cwiseAbs().mean();
            qInfo("brand: streamed frames %.4f from the whole solve, spread %.4f", difference.cwiseAbs().mean(), spread);
            QVERIFY(difference.cwiseAbs().mean() <= 0.03 * spread);
        } else {
            QCOMPARE(difference.cwiseAbs().maxCoeff(), 0.0);
        }
        // Another AAM: a clear error.
        g = runLipsync({"generate", "--model", model, "--labels", m_labels + "/real.TextGrid", "--out", out,
                        "--aam", "other-aam"});
        QCOMPARE(g.exitCode, 1);
        QVERIFY(g.err.contains("aam-test") && g.err.contains("other-aam"));
    }

    // SLDS is plain maximum likelihood unless --bound-a (or --bound-a-max) asks for the stability
    // bound on a.
    void sldsBoundOnA()
    {
        auto largestA = [](const QString &path) {
            QFile file(path);
            file.open(QIODevice::ReadOnly);
            double largest = 0.0;
            const QJsonArray A = QJsonDocument::fromJson(file.readAll()).object().value("parameters").toObject().value("A").toArray();
            for (const QJsonValue &matrix : A)
                for (const QJsonValue &row : matrix.toArray())
                    for (const QJsonValue &x : row.toArray())
                        largest = std::max(largest, std::abs(x.toDouble()));
            return largest;
        };
        const QString plain = m_dir.filePath("slds-plain.json"), bounded = m_dir.filePath("slds-bounded.json");
        for (const QStringList &extra : {QStringList{}, QStringList{"--bound-a-max", "0.5"}}) {
            const Run r = runLipsync(QStringList{"train", "--kind", "slds", "--features", m_features, "--labels", m_labels,
                                                 "--out", extra.isEmpty() ? plain : bounded, "--max-iterations", "20"}
                                     + extra);
            QVERIFY2(r.exitCode == 0, r.err.constData());
        }
        QVERIFY(largestA(plain) > 0.5);
        QVERIFY2(largestA(bounded) <= 0.5, qPrintable(QString::number(largestA(bounded))));
        const Run bad = runLipsync({"train", "--kind", "slds", "--features", m_features, "--labels", m_labels,
                                    "--out", bounded, "--bound-a", "--bound-a-max", "-1"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains("--bound-a-max"));
    }

    void generatesFromFrameList()
    {
        const QString list = m_dir.filePath(QStringLiteral("frames.txt"));
        std::ofstream(list.toStdString()) << "sil\nsil\nB\nIH1\nIH1\nN\nsil\n";
        const QString out = m_dir.filePath(QStringLiteral("list.csv"));
        const Run g = runLipsync({"generate", "--model", m_dir.filePath("dpds.json"), "--labels", list, "--out", out});
        QVERIFY2(g.exitCode == 0, g.err.constData());
        QCOMPARE(readFeatureCsv(out.toStdString()).values.rows(), Eigen::Index(7));
    }

    void evaluates()
    {
        const QString csv = m_dir.filePath(QStringLiteral("eval.csv"));
        const Run r = runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--folds", "4",
                                  "--kinds", "hmm,brand,dpds", "--csv", csv, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o.value("folds").toInt(), 4);
        const QJsonObject models = o.value("models").toObject();
        QCOMPARE(models.keys().size(), 3);
        for (const QString &kind : {QStringLiteral("hmm"), QStringLiteral("brand"), QStringLiteral("dpds")}) {
            const QJsonObject m = models.value(kind).toObject();
            for (const char *metric : {"l1", "rms", "linf", "loglik"}) {
                const QJsonObject s = m.value(QLatin1String(metric)).toObject();
                QVERIFY(s.contains("mean") && s.contains("ci95"));
                QCOMPARE(s.value("folds").toArray().size(), 4);
            }
            QVERIFY(m.value("trainingSeconds").toDouble() >= 0);
        }
        QVERIFY(QFile::exists(csv));
    }

    // --exclude leaves sequences out of training (a hold-out): the model then differs from one
    // trained on everything; a name that is not in the data is a usage error, not ignored.
    void excludesSequences()
    {
        auto hmmMean = [&](const QStringList &extra) {
            const QString out = m_dir.filePath(QStringLiteral("hmm-%1.json").arg(extra.size()));
            const Run r = runLipsync(QStringList{"train", "--kind", "hmm", "--features", m_features, "--labels",
                                                 m_labels, "--out", out} + extra);
            if (r.exitCode != 0)
                qWarning("%s", r.err.constData());
            return r.exitCode == 0 ? loadModel(out.toStdString()) : nullptr;
        };
        const auto all = hmmMean({});
        const auto held = hmmMean({"--exclude", "clip0,clip1,clip2"});
        QVERIFY(all && held);
        const std::vector<int> labels(30, PhoneSet::index("AA"));
        QVERIFY((all->generateMostLikely(labels) - held->generateMostLikely(labels)).cwiseAbs().maxCoeff() > 1e-9);
        // The footage's phone coverage in the report, and a warning for what it lacks.
        const Run report = runLipsync({"train", "--kind", "hmm", "--features", m_features, "--labels", m_labels,
                                       "--out", m_dir.filePath(QStringLiteral("c.json")), "--json"});
        QVERIFY2(report.exitCode == 0, report.err.constData());
        const QJsonObject coverage = parseJsonObject(report.out).value("coverage").toObject();
        QVERIFY(coverage.value("speechSeconds").toDouble() > 10);
        const bool lacking = !coverage.value("unseen").toArray().isEmpty() || !coverage.value("rare").toArray().isEmpty();
        QVERIFY(lacking); // the synthetic clips hold 5 phones, "real" not all of the rest
        QCOMPARE(coverage.value("advice").toString().isEmpty(), !lacking);
        QVERIFY2(report.err.contains("warning:"), report.err.constData());
        const Run typo = runLipsync({"train", "--kind", "hmm", "--features", m_features, "--labels", m_labels, "--out",
                                     m_dir.filePath(QStringLiteral("x.json")), "--exclude", "clip99"});
        QCOMPARE(typo.exitCode, 2);
        QVERIFY2(typo.err.contains("--exclude: no sequence 'clip99'"), typo.err.constData());
    }

    // --paper: the paper's models exactly (docs/models.md §8). The DPDS by Algorithm 1 differs
    // from the default's exact weighted solve; the baseline and Brand (diagonal) do not; an option
    // that would change one of the preset's models is refused.
    void evaluatesThePaperPreset()
    {
        auto l1 = [&](const QStringList &extra) {
            QStringList args{"evaluate", "--features", m_features, "--labels", m_labels, "--folds", "4",
                             "--kinds", "hmm,brand,dpds", "--json"};
            const Run r = runLipsync(args + extra);
            QMap<QString, double> out;
            if (r.exitCode != 0) {
                qWarning("%s", r.err.constData());
                return out;
            }
            const QJsonObject models = QJsonDocument::fromJson(r.out).object().value("models").toObject();
            for (const QString &kind : models.keys())
                out[kind] = models.value(kind).toObject().value("l1").toObject().value("mean").toDouble();
            return out;
        };
        const QMap<QString, double> plain = l1({});
        const QMap<QString, double> paper = l1({"--paper"});
        QCOMPARE(paper.size(), 3);
        for (const QString &kind : paper.keys())
            QVERIFY2(std::isfinite(paper[kind]) && paper[kind] > 0, qPrintable(kind));
        QCOMPARE(paper["hmm"], plain["hmm"]);
        QCOMPARE(paper["brand"], plain["brand"]);
        QVERIFY(paper["dpds"] != plain["dpds"]);
        const Run refused = runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--paper",
                                        "--compensate-variance"});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("--paper cannot be combined with --compensate-variance"), refused.err.constData());
    }

    // --project DIR gives the same data as the folders: features from the project's CSVs, frame
    // labels voted from its phone tiers.
    void trainsFromProject()
    {
        Project project;
        project.name = "synthetic";
        const QDir features(m_features);
        for (const QString &csv : features.entryList({QStringLiteral("*.csv")}, QDir::Files, QDir::Name)) {
            const QString name = csv.chopped(4);
            Sequence s;
            s.id = name.toStdString();
            s.mediaFile = "media/" + s.id + ".mpg";
            s.features = readFeatureCsv(features.filePath(csv).toStdString()).values;
            s.frameCount = int(s.features.rows());
            s.phones = readPhoneTier((m_labels + "/" + name + (name == "real" ? ".TextGrid" : ".lab")).toStdString());
            s.phones.name = "phones";
            project.sequences.push_back(std::move(s));
        }
        const QString folder = m_dir.filePath(QStringLiteral("project"));
        project.save(folder.toStdString());

        const QString a = m_dir.filePath(QStringLiteral("from-project.model"));
        const QString b = m_dir.filePath(QStringLiteral("from-folders.model"));
        const Run fromProject = runLipsync({"train", "--kind", "hmm", "--project", folder, "--out", a, "--json"});
        QVERIFY2(fromProject.exitCode == 0, fromProject.err.constData());
        const Run fromFolders = runLipsync({"train", "--kind", "hmm", "--features", m_features, "--labels",
                                            m_labels, "--out", b, "--json"});
        QVERIFY2(fromFolders.exitCode == 0, fromFolders.err.constData());
        const QJsonObject p = QJsonDocument::fromJson(fromProject.out).object();
        const QJsonObject f = QJsonDocument::fromJson(fromFolders.out).object();
        QCOMPARE(p.value("sequences").toInt(), f.value("sequences").toInt());
        QCOMPARE(p.value("frames").toDouble(), f.value("frames").toDouble());
        QVERIFY(std::abs(p.value("loglikPerFrame").toDouble() - f.value("loglikPerFrame").toDouble()) < 1e-9);

        const Run evaluation = runLipsync({"evaluate", "--project", folder, "--folds", "3", "--kinds", "hmm", "--json"});
        QVERIFY2(evaluation.exitCode == 0, evaluation.err.constData());

        // Brand's covariance chosen by cross-validation: the report says which, and the held-out
        // errors that chose it; the model file keeps the same.
        const QString cv = m_dir.filePath(QStringLiteral("brand-cv.model"));
        const Run chosen = runLipsync({"train", "--kind", "brand", "--project", folder, "--covariance", "cv", "--out", cv,
                                       "--json"});
        QVERIFY2(chosen.exitCode == 0, chosen.err.constData());
        const QJsonObject c = QJsonDocument::fromJson(chosen.out).object();
        const QJsonObject choice = c.value("covarianceChoice").toObject();
        QVERIFY2(choice.value("folds").toInt() >= 2, chosen.out.constData());
        QVERIFY(choice.value("diagonalL1").toDouble() > 0 && choice.value("fullL1").toDouble() > 0);
        QCOMPARE(c.value("covariance").toString(),
                 choice.value("fullL1").toDouble() < choice.value("diagonalL1").toDouble() ? "full" : "diagonal");
        QFile file(cv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject saved = QJsonDocument::fromJson(file.readAll()).object().value("parameters").toObject();
        QCOMPARE(saved.value("covariance").toString(), c.value("covariance").toString());
        QCOMPARE(saved.value("covarianceChoice").toObject(), choice);
        const Run diagonal = runLipsync({"train", "--kind", "brand", "--project", folder, "--out", cv, "--json"});
        QCOMPARE(QJsonDocument::fromJson(diagonal.out).object().value("covariance").toString(), "diagonal");
        QVERIFY(!QJsonDocument::fromJson(diagonal.out).object().contains("covarianceChoice"));
        QCOMPARE(runLipsync({"train", "--kind", "brand", "--project", folder, "--covariance", "both", "--out", cv}).exitCode, 2);

        // A project without features: exit 1, one line naming the manifest.
        Project empty;
        Sequence bare;
        bare.id = "bare";
        bare.mediaFile = "media/bare.mpg";
        bare.frameCount = 75;
        empty.sequences.push_back(bare);
        const QString emptyFolder = m_dir.filePath(QStringLiteral("empty-project"));
        empty.save(emptyFolder.toStdString());
        const Run none = runLipsync({"train", "--kind", "hmm", "--project", emptyFolder, "--out", a});
        QCOMPARE(none.exitCode, 1);
        QVERIFY(none.err.contains("project.json"));
        QVERIFY(none.err.contains("no sequence has both face features and a phone alignment"));
        QCOMPARE(none.err.count('\n'), 1);
        // Both sources at once is a usage error.
        QCOMPARE(runLipsync({"train", "--kind", "hmm", "--project", folder, "--features", m_features,
                             "--labels", m_labels, "--out", a}).exitCode, 2);
    }

    // Phone times are in seconds, so the frame labels depend on the video's rate: train takes it
    // from the features file ("# fps=..."), refuses a file that records none unless --fps gives
    // it, and refuses a --fps that contradicts the file; the model records the rate, and generate
    // generates at it.
    void takesTheFrameRateFromTheFeatures()
    {
        QTemporaryDir dir;
        const QString features = dir.filePath("f"), labels = dir.filePath("l");
        QDir().mkpath(features);
        QDir().mkpath(labels);
        // Every phone has its own constant features, so the HMM-mean reproduces the features
        // exactly from the right frame labels and not from labels voted at another rate.
        const double ntsc = 30000.0 / 1001.0;
        std::mt19937 rng(11);
        const std::vector<int> states{PhoneSet::index("B"), PhoneSet::index("IH"), PhoneSet::index("N"),
                                      PhoneSet::index("AA")};
        const std::vector<int> frameLabels = test::randomLabels(rng, 300, states, 3);
        Eigen::MatrixXd Y(Eigen::Index(frameLabels.size()), 1);
        for (size_t t = 0; t < frameLabels.size(); ++t)
            Y(Eigen::Index(t), 0) = frameLabels[t];
        writeFeatureCsv((features + "/clip.csv").toStdString(), Y, {}, ntsc);
        writeLab((labels + "/clip.lab").toStdString(), frameLabels, ntsc);
        const QString model = dir.filePath("hmm.json");
        Run r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QString out = dir.filePath("gen.csv");
        // The model records the rate, and generate takes it from the model.
        r = runLipsync({"generate", "--model", model, "--labels", labels + "/clip.lab", "--frames",
                        QString::number(Y.rows()), "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const FeatureTable generated = readFeatureCsv(out.toStdString());
        QCOMPARE(generated.values, Y);
        QCOMPARE(generated.frameRate, 29.97002997002997);
        r = runLipsync({"generate", "--model", model, "--labels", labels + "/clip.lab", "--fps", "25", "--out", out});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("hmm.json") && r.err.contains("trained at 29.97") && r.err.contains("at 25 "),
                 r.err.constData());
        // A contradicting --fps is refused, naming the file and both rates.
        r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model,
                        "--fps", "25"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("clip.csv") && r.err.contains("29.97002997") && r.err.contains("25 fps"),
                 r.err.constData());
        // A file that records no rate: refused without --fps, trained with it.
        writeFeatureCsv((features + "/clip.csv").toStdString(), Y);
        r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("clip.csv") && r.err.contains("no frame rate") && r.err.contains("--fps"),
                 r.err.constData());
        QCOMPARE(r.err.count('\n'), 1);
        r = runLipsync({"evaluate", "--features", features, "--labels", labels, "--folds", "2"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("no frame rate"), r.err.constData());
        r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model,
                        "--fps", "29.97002997002997"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
    }

    void badInput()
    {
        const QString model = m_dir.filePath(QStringLiteral("bad.json"));
        // Bad usage: exit 2.
        QCOMPARE(runLipsync({"train", "--kind", "lstm", "--features", m_features, "--labels", m_labels, "--out", model}).exitCode, 2);
        QCOMPARE(runLipsync({"train", "--features", m_features}).exitCode, 2);
        QCOMPARE(runLipsync({"generate", "--model", model}).exitCode, 2);
        QCOMPARE(runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--folds", "1"}).exitCode, 2);
        // --realism renders into a project's media: features and labels alone are bad usage, and so
        // are the options that only the error metrics have.
        Run realism = runLipsync({"evaluate", "--realism", "--features", m_features, "--labels", m_labels});
        QCOMPARE(realism.exitCode, 2);
        QVERIFY2(realism.err.contains("--project"), realism.err.constData());
        QCOMPARE(runLipsync({"evaluate", "--realism", "--project", m_dir.path(), "--csv", "x.csv"}).exitCode, 2);
        QCOMPARE(runLipsync({"evaluate", "--realism", "--project", m_dir.path(), "--max-lag", "-1"}).exitCode, 2);
        QCOMPARE(runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--max-lag", "3"}).exitCode, 2);
        QCOMPARE(runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--observer-crf", "0"}).exitCode, 2);
        realism = runLipsync({"evaluate", "--realism", "--project", m_dir.path(), "--observer-crf", "52"});
        QCOMPARE(realism.exitCode, 2);
        QVERIFY2(realism.err.contains("observer-crf"), realism.err.constData());
        realism = runLipsync({"evaluate", "--help"});
        QCOMPARE(realism.exitCode, 0);
        QVERIFY(realism.out.contains("--realism") && realism.out.contains("dlib"));
        QCOMPARE(runLipsync({"train", "--kind", "hmm", "--features", m_features, "--labels", m_labels, "--out", model, "--bogus"}).exitCode, 2);
        // Bad data: exit 1 with one line naming the file.
        QTemporaryDir bad;
        const QString features = bad.filePath("f"), labels = bad.filePath("l");
        QDir().mkpath(features);
        QDir().mkpath(labels);
        std::ofstream((features + "/nan.csv").toStdString()) << "frame,p0\n0,1.0\n1,nan\n";
        std::ofstream((labels + "/nan.lab").toStdString()) << "0 0.08 sil\n";
        Run r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("nan.csv") && r.err.count('\n') == 1);
        std::ofstream((features + "/nan.csv").toStdString()) << "frame,p0\n0,1.0\n1,2.0\n";
        std::ofstream((features + "/orphan.csv").toStdString()) << "frame,p0\n0,1.0\n";
        r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model, "--fps", "25"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("orphan"));
        QFile::remove(features + "/orphan.csv");
        std::ofstream((labels + "/nan.lab").toStdString()) << "0 0.08 QQ\n";
        r = runLipsync({"train", "--kind", "hmm", "--features", features, "--labels", labels, "--out", model, "--fps", "25"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("QQ") && r.err.contains("nan.lab"));
        // Too few sequences for the folds; a model file that is not one.
        r = runLipsync({"evaluate", "--features", m_features, "--labels", m_labels, "--folds", "20"});
        QCOMPARE(r.exitCode, 1);
        std::ofstream(model.toStdString()) << "{}";
        r = runLipsync({"generate", "--model", model, "--labels", m_labels + "/real.TextGrid", "--out", bad.filePath("x.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("bad.json"));
    }
};

QTEST_GUILESS_MAIN(TestDynamicsCli)
#include "tst_dynamicscli.moc"
