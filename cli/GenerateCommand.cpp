// lipsync generate: the most likely feature trajectory of a trained model for a label sequence.
#include "Command.h"

#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/FeatureCsv.h"

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

const char *kGenerateUsage =
    "usage: lipsync generate --model MODEL --labels FILE --out FEATURES.csv\n"
    "                        [--fps 25] [--frames N] [--aam ID] [--stream] [--json]\n"
    "  FILE: NAME.TextGrid (phones tier), NAME.lab (start end phone, seconds) or a list of one\n"
    "  phone per frame (any other extension). --stream uses the frame-by-frame generator.";

int runGenerate(const QStringList &argv)
{
    const Arguments args(argv);
    const QStringList unknown = args.unknown({"model", "labels", "out", "fps", "frames", "aam", "stream", "json"});
    if (!unknown.isEmpty() || !args.positional().isEmpty())
        return fail(QStringLiteral("unknown argument %1\n").arg((unknown + args.positional()).first())
                        + QString::fromLatin1(kGenerateUsage),
                    2);
    const QString modelPath = args.value(QStringLiteral("model"));
    const QString labelsPath = args.value(QStringLiteral("labels"));
    const QString out = args.value(QStringLiteral("out"));
    if (modelPath.isEmpty() || labelsPath.isEmpty() || out.isEmpty())
        return fail(QString::fromLatin1(kGenerateUsage), 2);
    bool ok = false;
    const double fps = args.value(QStringLiteral("fps"), QStringLiteral("25")).toDouble(&ok);
    if (!ok || !(fps > 0))
        return fail(QStringLiteral("--fps must be a positive number"), 2);
    int frames = 0;
    if (args.has(QStringLiteral("frames"))) {
        frames = args.value(QStringLiteral("frames")).toInt(&ok);
        if (!ok || frames < 1)
            return fail(QStringLiteral("--frames must be a positive integer"), 2);
    }
    std::string aam;
    const auto model = loadModel(modelPath.toStdString(), args.value(QStringLiteral("aam")).toStdString(), &aam);
    const std::vector<int> labels = readFrameLabels(labelsPath.toStdString(), fps, frames);
    Eigen::MatrixXd Y;
    if (args.flag(QStringLiteral("stream"))) {
        auto stream = model->streamer();
        Y.resize(Eigen::Index(labels.size()), model->dimension());
        Eigen::VectorXd frame(model->dimension());
        Eigen::Index next = 0;
        for (int label : labels) {
            stream->push(label);
            while (stream->pop(frame))
                Y.row(next++) = frame.transpose();
        }
        stream->finish();
        while (stream->pop(frame))
            Y.row(next++) = frame.transpose();
    } else {
        Y = model->generate(labels);
    }
    writeFeatureCsv(out.toStdString(), Y, {}, fps);
    if (args.flag(QStringLiteral("json"))) {
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
    QStringLiteral("generate"), QStringLiteral("generate face features from phone labels with a trained model"),
    &runGenerate};

} // namespace
