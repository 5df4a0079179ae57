// lipsync evaluate: k-fold cross-validation of the dynamic models (docs/models.md §6).
#include "AlignerSupport.h"
#include "CommandLine.h"
#include "Compositing.h"
#include "DynamicModelOptions.h"
#include "MouthPriorOptions.h"
#include "TrainingData.h"

#include "align/ShippedAlignerModel.h"
#include "eval/Evaluation.h"
#include "eval/RealismReport.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>

#include <cmath>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

void printRealism(const RealismResult &result)
{
    std::printf("realism, %d-fold cross-validation, %d sequences, %lld frames (%lld without a face, skipped); "
                "%d of %d /p b m/ segments closed in the recordings\n",
                result.folds, result.sequences, result.frames, result.skippedFrames, result.closedRecorded,
                result.bilabials);
    // One row per measure, one column per method.
    std::printf("%-25s", "");
    for (const RealismMethod &m : result.methods)
        std::printf(" %20s", m.kind.c_str());
    std::printf("\n");
    for (const std::string &metric : realismMetrics()) {
        std::printf("%-25s", metric.c_str());
        for (const RealismMethod &m : result.methods) {
            const MetricSummary &s = m.metrics.at(metric);
            if (!std::isfinite(s.mean))
                std::printf(" %20s", "-");
            else if (std::isfinite(s.ci95))
                std::printf(" %11.3g ± %-6.2g", s.mean, s.ci95);
            else
                std::printf(" %11.3g %-8s", s.mean, "");
        }
        std::printf("\n");
    }
    std::printf("correlation: Pearson of the lip opening with the recording's (speech: from the first to the last "
                "spoken phone; control: each recording against another sequence's render); articulation, "
                "closure, sharpness: generated / recorded; closureRecall: /p b m/ closed in both / in the "
                "recording; falseClosures: closures outside /p b m/ per second of speech; lag: frames, generated "
                "minus recorded; seamDeltaE: CIE Lab dE across the synthesised region's edge (Recorded: the "
                "recording at the same pixels; Natural: a real edge there, for a drawn inside the recording's own "
                "inner-lip edge at that opening); observer: a classifier's held-out accuracy telling the encoded "
                "render from the encoded recording (0.5: it cannot); shapeCorrelation: the method's own inner-lip "
                "gap (what the animation exports carry) against the opening on its render; "
                "shiftedSpeechCorrelation: speech correlation with each frame drawn into the clip's footage half "
                "its length away, whose mouth does not follow the recording (as new speech in other footage)\n");
}

int runRealism(const CommandLine &args, const EvaluationOptions &evaluation)
{
    if (args.isSet(QStringLiteral("csv")) || args.isSet(QStringLiteral("fps")))
        throw UsageError(QStringLiteral("--csv and --fps do not apply to --realism"));
    if (!args.isSet(QStringLiteral("project")) || args.isSet(QStringLiteral("features")) || args.isSet(QStringLiteral("labels")))
        throw UsageError(QStringLiteral("--realism needs --project DIR (the media and the AAM)"));
    RealismOptions options;
    options.crossValidation = evaluation;
    options.maxLag = args.integer(QStringLiteral("max-lag"), 0);
    if (args.isSet(QStringLiteral("observer-crf")))
        options.observerCrf = args.integer(QStringLiteral("observer-crf"), 0, 51);
    options.mouthPrior = mouthPriorFrom(args, &options.mouthPriorWeight);
    options.dlibPredictor = args.value(QStringLiteral("dlib")).toStdString();
    const bool paper = args.isSet(QStringLiteral("paper"));
    if (paper)
        for (const CommandOption &option : Compositing::options())
            if (args.isSet(option.name))
                throw UsageError(QStringLiteral("--paper cannot be combined with --%1").arg(option.name));
    options.composite = paper ? CompositeOptions::paper() : Compositing::from(args);
    options.closeBilabials = !paper && Compositing::closesLips(args);
    options.keepPosture = !paper && Compositing::keepsPosture(args);
    if (args.isSet(QStringLiteral("live"))) {
        options.liveAcousticModel = alignerModelOrDefault({}, QStringLiteral("evaluate --live")).toStdString();
        options.liveBigram = shippedPhoneBigramPath();
        if (options.liveBigram.empty())
            throw Error("no shipped phone bigram for --live (resources/aligner/grid-s1.bigram)");
    }
    if (args.isSet(QStringLiteral("exemplars"))) {
        const QStringList values = args.list(QStringLiteral("exemplars"));
        ExemplarSelection::Options e;
        bool ok = values.size() == 3;
        if (ok) {
            bool a = false, b = false, c = false;
            e.candidates = values[0].toInt(&a);
            e.join = values[1].toDouble(&b);
            e.cut = values[2].toDouble(&c);
            ok = a && b && c && e.candidates > 0 && e.join >= 0 && e.cut >= 0;
        }
        if (!ok)
            throw UsageError(QStringLiteral("--exemplars takes K,JOIN,CUT (e.g. 16,1,0.5)"));
        options.exemplars = e;
    }
    const Project project = Project::load(args.value(QStringLiteral("project")).toStdString());
    Feedback feedback;
    const RealismResult result = evaluateRealism(project, options, feedback);
    if (args.isSet(QStringLiteral("json")))
        printJson(result.toJson());
    else
        printRealism(result);
    return 0;
}

int runEvaluate(const CommandLine &args)
{
    const bool realism = args.isSet(QStringLiteral("realism"));
    if (!realism) {
        QStringList realismOnly{QStringLiteral("max-lag"), QStringLiteral("dlib"), QStringLiteral("live"),
                                QStringLiteral("exemplars"), QStringLiteral("observer-crf"), QStringLiteral("prior"),
                                QStringLiteral("prior-file"), QStringLiteral("prior-weight")};
        for (const CommandOption &option : Compositing::options())
            realismOnly << option.name;
        for (const QString &option : realismOnly)
            if (args.isSet(option))
                throw UsageError(QStringLiteral("--%1 applies to --realism only").arg(option));
    }
    EvaluationOptions options;
    options.folds = args.integer(QStringLiteral("folds"), 2);
    options.seed = args.unsignedInteger(QStringLiteral("seed"));
    if (args.isSet(QStringLiteral("kinds"))) {
        options.kinds.clear();
        for (const QString &k : args.list(QStringLiteral("kinds"))) {
            if (!isDynamicModelKind(k.toStdString()))
                throw UsageError(QStringLiteral("--kinds: unknown model '%1' (%2)")
                                     .arg(k, QString::fromStdString(modelKindIdList(", "))));
            options.kinds.push_back(k.toStdString());
        }
        if (options.kinds.empty())
            throw UsageError(QStringLiteral("--kinds is empty"));
    }
    options.modelOptions = dynamicModelOptionsFrom(args);
    if (args.isSet(QStringLiteral("train-minutes")))
        options.trainingSpeechSeconds = 60.0 * args.positiveNumber(QStringLiteral("train-minutes"));
    if (realism)
        return runRealism(args, options);

    const std::vector<LabelledSequence> sequences = loadTrainingData(args);
    Feedback feedback;
    const EvaluationResult result = evaluateModels(sequences, options, feedback);
    if (args.isSet(QStringLiteral("csv")))
        writeFileAtomically(args.value(QStringLiteral("csv")).toStdString(), result.toCsv());
    if (args.isSet(QStringLiteral("json"))) {
        printJson(result.toJson());
        return 0;
    }
    std::printf("%d-fold cross-validation, %d sequences, %lld frames\n", result.folds, result.sequences,
                result.frames);
    std::printf("%-6s %22s %22s %22s %22s %10s\n", "model", "L1", "RMS", "Linf", "loglik/frame", "train s");
    for (const ModelEvaluation &m : result.models) {
        double seconds = 0;
        for (double s : m.trainingSeconds)
            seconds += s;
        std::printf("%-6s", m.kind.c_str());
        for (const std::string &metric : evaluationMetrics())
            std::printf(" %12.5g ± %-7.3g", m.metrics.at(metric).mean, m.metrics.at(metric).ci95);
        std::printf(" %10.3f\n", seconds);
    }
    std::printf("%s\n", logLikelihoodNote());
    return 0;
}

const CommandRegistration registration{
    CommandSpec{
        QStringLiteral("evaluate"),
        QStringLiteral("cross-validate the dynamic models (L1, RMS, Linf, log-likelihood; --realism: rendered lips)"),
        QStringLiteral(
            "k-fold cross-validation of the dynamic models, split by sequence (docs/models.md 6): the L1, RMS and "
            "Linf error of every model's generation against the held-out features, and their log-likelihood.\n"
            "--realism: on the same held-out folds, render every model's generation (and the tracked parameters' "
            "re-synthesis, \"tracked\") into the recording's frames and compare the lips measured by dlib's "
            "68-point predictor with the recording's: opening correlation, articulation (s.d. ratio), /p b m/ "
            "closures (ratio), audio-visual lag (frames, generated minus recorded, searched within --max-lag), "
            "mouth sharpness (ratio) and the colour step across the seam (CIE Lab dE; beside it the recording's at the "
            "same pixels, and a real edge's: for a drawn inside, the recording's own inner-lip edge). Needs --project "
            "with its media and AAM, and Debian's libdlib-data (or --dlib FILE). docs/models.md 6.5"),
        {{QStringLiteral("folds"), QStringLiteral("K"), QStringLiteral("the number of folds (>= 2)"), QStringLiteral("10")},
         {QStringLiteral("seed"), QStringLiteral("S"), QStringLiteral("the seed of the random split into folds"),
          QStringLiteral("2007")},
         {QStringLiteral("kinds"), QString::fromStdString(modelKindIdList(",", ",")),
          QStringLiteral("the models to evaluate (default: all)")},
         {QStringLiteral("train-minutes"), QStringLiteral("M"),
          QStringLiteral("train each fold's models on only M minutes of speech of its training folds (sequences "
                         "drawn at random until their speech reaches M; a learning curve)")},
         {QStringLiteral("csv"), QStringLiteral("FILE"), QStringLiteral("also write the results as CSV")},
         {QStringLiteral("realism"), {}, QStringLiteral("evaluate the rendered lips instead (see above)")},
         {QStringLiteral("max-lag"), QStringLiteral("FRAMES"),
          QStringLiteral("--realism: the audio-visual lags searched"), QStringLiteral("5")},
         {QStringLiteral("dlib"), QStringLiteral("FILE"),
          QStringLiteral("--realism: dlib's 68-point shape predictor (default: Debian's libdlib-data)")},
         {QStringLiteral("live"), {},
          QStringLiteral("--realism: also every model driven live, its phones recognised from the sound as it "
                         "streams in (the shipped aligner model and phone bigram, as `lipsync live`), reported as "
                         "\"live KIND\"")},
         {QStringLiteral("observer-crf"), QStringLiteral("N"),
          QStringLiteral("--realism: the x264 quality the machine observer's recording and renders are encoded at "
                         "(default 0: lossless, colour at full resolution; 20: the export's)")},
         {QStringLiteral("exemplars"), QStringLiteral("K,JOIN,CUT"),
          QStringLiteral("--realism: also every model's trajectory replaced by the training folds' recorded frames "
                         "nearest it (render/ExemplarSelection: K candidates a frame, the join and cut weights), "
                         "reported as \"KIND exemplars\"")}},
        {}}
        .add(trainingDataOptions())
        .add(dynamicModelOptions())
        .add(Compositing::options())
        .add(mouthPriorOptions(QStringLiteral("--realism: "))),
    &runEvaluate};

} // namespace
