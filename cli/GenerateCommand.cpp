// lipsync generate: the most likely feature trajectory of a trained model for a label sequence.
#include "CommandLine.h"
#include "DynamicModelOptions.h"

#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/FeatureCsv.h"
#include "util/Error.h"

#include <cmath>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runGenerate(const CommandLine &args)
{
    const QString modelPath = args.value(QStringLiteral("model"));
    const QString labelsPath = args.value(QStringLiteral("labels"));
    const QString out = args.value(QStringLiteral("out"));
    const int frames = args.isSet(QStringLiteral("frames")) ? args.integer(QStringLiteral("frames"), 1) : 0;
    std::string aam;
    const auto model = loadModel(modelPath.toStdString(), modelAamIdentifier(args), &aam);
    // The model's dynamics are per frame: it generates at the rate it was trained at.
    double fps = model->frameRate();
    if (args.isSet(QStringLiteral("fps"))) {
        const double given = args.positiveNumber(QStringLiteral("fps"));
        if (fps > 0 && std::abs(given - fps) > 1e-6 * fps)
            throw Error(QStringLiteral("the model was trained at %1 frames/s: its dynamics are per frame, so "
                                       "generating at %2 would change their timing (leave out --fps)")
                            .arg(fps)
                            .arg(given)
                            .toStdString(),
                        modelPath.toStdString());
        fps = given;
    }
    if (!(fps > 0))
        throw Error("the model records no frame rate: give the rate it was trained at with --fps",
                    modelPath.toStdString());
    const std::vector<int> labels = readFrameLabels(labelsPath.toStdString(), fps, frames);
    const Eigen::MatrixXd Y =
        args.isSet(QStringLiteral("stream")) ? model->generateStreamed(labels) : model->generate(labels);
    writeFeatureCsv(out.toStdString(), Y, {}, fps);
    if (args.isSet(QStringLiteral("json"))) {
        QJsonObject o;
        o[QStringLiteral("kind")] = QString::fromStdString(model->kind());
        o[QStringLiteral("aam")] = QString::fromStdString(aam);
        o[QStringLiteral("frames")] = int(Y.rows());
        o[QStringLiteral("dimension")] = int(Y.cols());
        o[QStringLiteral("out")] = out;
        printJson(o);
    } else {
        std::printf("generated %d frames (d = %d) with the %s model; wrote %s\n", int(Y.rows()),
                    int(Y.cols()), model->kind().c_str(), out.toUtf8().constData());
    }
    return 0;
}

const CommandRegistration registration{
    {QStringLiteral("generate"),
     QStringLiteral("generate face features from phone labels with a trained model"),
     QStringLiteral("The most likely feature trajectory of a trained dynamic model for a sequence of phone labels, "
                    "written as a feature CSV."),
     {{QStringLiteral("model"), QStringLiteral("MODEL"), QStringLiteral("a trained dynamic model (lipsync train)"), {},
       CommandOption::Required},
      {QStringLiteral("labels"), QStringLiteral("FILE"),
       QStringLiteral("the phones: NAME.TextGrid (phones tier), NAME.lab (start end phone, seconds) or a list of one "
                      "phone per frame (any other extension)"),
       {}, CommandOption::Required},
      {QStringLiteral("out"), QStringLiteral("FEATURES.csv"), QStringLiteral("the features to write"), {},
       CommandOption::Required},
      {QStringLiteral("fps"), QStringLiteral("RATE"),
       QStringLiteral("frames per second of the generated features, for a model file that records none (the "
                      "rate the model was trained at)")},
      {QStringLiteral("frames"), QStringLiteral("N"), QStringLiteral("generate N frames (default: as the labels last)")},
      modelAamOption(QStringLiteral("refuse a model trained for another AAM than this one (its file or its "
                                    "identifier)")),
      {QStringLiteral("stream"), {}, QStringLiteral("use the frame-by-frame generator")}},
     {}},
    &runGenerate};

} // namespace
