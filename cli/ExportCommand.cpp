// `lipsync export video`: a clip (optionally beside a second clip, e.g. real next to generated)
// re-encoded as MP4 (H.264 + the first clip's sound as AAC), or as a PNG sequence. The same
// exporter backs the studio's export menu and `lipsync render`.
#include "Command.h"

#include "io/AudioDecoder.h"
#include "io/VideoReader.h"
#include "render/FrameComposition.h"
#include "render/ImageSequenceExporter.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QElapsedTimer>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runExportVideo(const QStringList &args)
{
    const Arguments arguments(args, Arguments::defaultBooleanFlags() << QStringLiteral("no-audio"));
    const QStringList unknown = arguments.unknown(
        {"media", "out", "png-dir", "beside", "labels", "crf", "no-audio", "json"});
    if (!unknown.isEmpty())
        return fail(QStringLiteral("export video: unknown option %1").arg(unknown.join(' ')), 2);
    const QString media = arguments.value("media");
    const QString out = arguments.value("out");
    const QString pngDir = arguments.value("png-dir");
    if (media.isEmpty() || (out.isEmpty() == pngDir.isEmpty()))
        return fail(QStringLiteral("usage: lipsync export video --media CLIP (--out OUT.mp4 | "
                                   "--png-dir DIR) [--beside OTHER_CLIP] "
                                   "[--labels LEFT,RIGHT] [--crf 20] [--no-audio] [--json]"),
                    2);
    bool ok = true;
    VideoExportOptions options;
    options.crf = arguments.value("crf", "20").toInt(&ok);
    if (!ok || options.crf < 0 || options.crf > 51)
        return fail(QStringLiteral("export video: --crf takes an integer in 0..51"), 2);

    VideoReader reader(media.toStdString());
    std::unique_ptr<VideoReader> other;
    if (arguments.has("beside"))
        other = std::make_unique<VideoReader>(arguments.value("beside").toStdString());
    std::vector<std::string> labels;
    for (const QString &label : arguments.value("labels").split(QLatin1Char(','), Qt::SkipEmptyParts))
        labels.push_back(label.trimmed().toStdString());
    if (!labels.empty() && labels.size() != (other ? 2u : 1u))
        return fail(QStringLiteral("export video: --labels takes one label per panel"), 2);

    options.setFrameRate(reader.frameRate());

    std::optional<AudioBuffer> audio;
    if (!arguments.flag("no-audio") && !out.isEmpty()) {
        try {
            // Sound and picture may start at different times in the source container.
            audio = alignAudioToVideo(AudioDecoder::decode(media.toStdString(), 0), reader.timestamp(0));
        } catch (const Error &e) {
            throw Error(e.reason() + " (use --no-audio to export the picture only)", e.file(), e.field());
        }
    }
    const int frames = other ? std::min(reader.frameCount(), other->frameCount()) : reader.frameCount();
    auto frameAt = [&](int i) {
        const cv::Mat frame = reader.frame(i);
        if (other)
            return composeSideBySide(frame, other->frame(i), labels.empty() ? std::string() : labels[0],
                                     labels.empty() ? std::string() : labels[1]);
        if (!labels.empty())
            return composeGrid({frame}, 1, labels);
        return frame;
    };

    Feedback feedback;
    QElapsedTimer timer;
    timer.start();
    QJsonObject result{{"media", media}};
    if (!out.isEmpty()) {
        const int written = exportVideo(out.toStdString(), frames, frameAt,
                                        audio ? &*audio : nullptr, feedback, options);
        result["out"] = out;
        result["frames"] = written;
        result["duration"] = written / options.frameRate();
        result["audio"] = bool(audio);
        if (audio)
            result["audioDuration"] = audio->duration();
    } else {
        const std::vector<std::string> paths = exportImageSequence(pngDir.toStdString(), frames, frameAt, feedback);
        result["pngDir"] = pngDir;
        result["frames"] = int(paths.size());
    }
    result["seconds"] = timer.elapsed() / 1000.0;
    if (arguments.flag("json"))
        printJson(result);
    else
        std::printf("%s: %d frames in %.2f s\n",
                    qPrintable(out.isEmpty() ? pngDir : out), result["frames"].toInt(),
                    result["seconds"].toDouble());
    return 0;
}

const CommandRegistration registration{
    QStringLiteral("export video"),
    QStringLiteral("re-encode a clip (or two side by side) as MP4 with its sound, or as PNGs"),
    &runExportVideo};

} // namespace
