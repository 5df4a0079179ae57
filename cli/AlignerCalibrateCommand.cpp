// lipsync aligner calibrate --media DIR --transcripts DIR --out MODEL [--aligner MODEL]
//                           [--pronunciations DICT] [--json]
// Learns an aligner model's word-boundary correction (align/BoundaryCorrection) from recordings
// whose transcripts carry word timings — GRID .align files, timed .lab files, TextGrids corrected
// in the studio's timeline — and writes the model with it: every alignment by that model then
// moves each word boundary by the median offset the model showed against those timings for
// boundaries like it. How much it helps is cross-validated over the recordings and reported; no
// correction is kept where it does not help.
#include "AlignerSupport.h"
#include "CommandLine.h"

#include "align/AlignerTrainer.h"
#include "util/Error.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;

namespace {

int runAlignerCalibrate(const cli::CommandLine &a)
{
    const bool json = a.isSet("json");
    const QString modelPath = cli::alignerModelOrDefault(a.value("aligner"), QStringLiteral("aligner calibrate"));
    QElapsedTimer timer;
    timer.start();
    AcousticModel model = AcousticModel::load(modelPath.toStdString());
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"));
    QJsonArray skipped;
    const std::vector<TrainingUtterance> utterances =
        cli::loadTranscribedFolder(a.value("media"), a.value("transcripts"), model, *lexicon, json, skipped);
    const auto timed = std::count_if(utterances.begin(), utterances.end(),
                                     [](const TrainingUtterance &u) { return !u.reference.intervals.empty(); });
    if (timed == 0)
        throw Error("no transcript with word timings (.align, a timed .lab or a .TextGrid) to calibrate on",
                    a.value("transcripts").toStdString());
    BoundaryCorrectionReport report;
    model.setBoundaryCorrection(AlignerTrainer::calibrate(model, utterances, {}, &report));
    model.save(a.value("out").toStdString());
    const double seconds = timer.elapsed() / 1000.0;
    if (json) {
        cli::printJson(QJsonObject{
            {QStringLiteral("model"), a.value("out")},
            {QStringLiteral("from"), modelPath},
            {QStringLiteral("recordings"), report.utterances},
            {QStringLiteral("wordsDiffer"), report.skipped},
            {QStringLiteral("boundaries"), report.boundaries},
            {QStringLiteral("minimumCount"), report.minimumCount},
            {QStringLiteral("entries"), report.entries},
            {QStringLiteral("withinToleranceBefore"), report.withinBefore},
            {QStringLiteral("withinToleranceAfter"), report.withinAfter},
            {QStringLiteral("skipped"), skipped},
            {QStringLiteral("seconds"), seconds},
        });
    } else if (report.minimumCount == 0) {
        std::printf("%d boundaries of %d recordings: a correction would not help (%.1f %% within 40 ms, "
                    "cross-validated); %s written without one\n",
                    report.boundaries, report.utterances, 100.0 * report.withinBefore, qPrintable(a.value("out")));
    } else {
        std::printf("%d boundaries of %d recordings: %.1f %% -> %.1f %% within 40 ms (cross-validated), "
                    "%d groups of at least %d; %.1f s -> %s\n",
                    report.boundaries, report.utterances, 100.0 * report.withinBefore, 100.0 * report.withinAfter,
                    report.entries, report.minimumCount, seconds, qPrintable(a.value("out")));
    }
    return 0;
}

const cli::CommandRegistration registration{
    cli::CommandSpec{QStringLiteral("aligner calibrate"),
     QStringLiteral("learn the aligner's word-boundary correction from transcripts with word timings"),
     QStringLiteral("Aligns recordings whose transcripts carry word timings (GRID .align, timed .lab, a TextGrid "
                    "corrected in the studio) with an aligner model, learns the median offset of its word "
                    "boundaries from those timings for each kind of boundary (onset, junction, offset; by the words "
                    "and phones that meet), and writes the model with that correction: every alignment by it then "
                    "moves its word boundaries by those offsets. The gain is cross-validated over the recordings "
                    "and reported; a correction that does not help is not kept."),
     {{QStringLiteral("out"), QStringLiteral("MODEL"), QStringLiteral("the calibrated aligner model to write"), {},
       cli::CommandOption::Required},
      {QStringLiteral("aligner"), QStringLiteral("MODEL"),
       QStringLiteral("the aligner model to calibrate (default: the shipped GRID s1 model, or $LIPSYNC_ALIGNER_MODEL)"),
       {}, cli::CommandOption::Optional, {QStringLiteral("model")}}},
     {}}
        .add(cli::transcribedFolderOptions()),
    &runAlignerCalibrate};

} // namespace
