// `lipsync export video`: a clip (optionally beside a second clip, e.g. real next to generated)
// re-encoded as MP4 (H.264 + the first clip's sound as AAC), or as a PNG sequence. The same
// exporter backs the studio's export menu and `lipsync render`.
#include "CommandLine.h"
#include "VideoOutput.h"

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

int runExportVideo(const CommandLine &arguments)
{
    const QString media = arguments.value("media");
    const VideoOutput output = VideoOutput::from(arguments, arguments.isSet("beside") ? 2 : 1);
    const QString &out = output.out;
    const QString &pngDir = output.pngDir;
    const std::vector<std::string> &labels = output.captions;
    VideoExportOptions options;
    options.crf = output.crf;

    VideoReader reader(media.toStdString());
    std::unique_ptr<VideoReader> other;
    if (arguments.isSet("beside"))
        other = std::make_unique<VideoReader>(arguments.value("beside").toStdString());

    const int frames = other ? std::min(reader.frameCount(), other->frameCount()) : reader.frameCount();
    // The source's frames at their own times (variable frame rates and 29.97 kept).
    options.setFrames(reader.clock().slice(0, frames));

    std::optional<AudioBuffer> audio;
    if (!arguments.isSet("no-audio") && !out.isEmpty()) {
        try {
            // Sound and picture may start at different times in the source container.
            audio = alignAudioToVideo(AudioDecoder::decode(media.toStdString(), 0), reader.timestamp(0));
        } catch (const Error &e) {
            throw Error(e.reason() + " (use --no-audio to export the picture only)", e.file(), e.field());
        }
    }
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
        result["duration"] = options.frames.duration();
        result["audio"] = bool(audio);
        if (audio)
            result["audioDuration"] = options.frames.duration(); // fitted to the frames
    } else {
        const std::vector<std::string> paths = exportImageSequence(pngDir.toStdString(), frames, frameAt, feedback);
        result["pngDir"] = pngDir;
        result["frames"] = int(paths.size());
    }
    result["seconds"] = timer.elapsed() / 1000.0;
    if (arguments.isSet("json"))
        printJson(result);
    else
        std::printf("%s: %d frames in %.2f s\n",
                    qPrintable(out.isEmpty() ? pngDir : out), result["frames"].toInt(),
                    result["seconds"].toDouble());
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("export video"),
     QStringLiteral("re-encode a clip (or two side by side) as MP4 with its sound, or as PNGs"),
     QStringLiteral("Re-encodes a clip, optionally beside a second clip (e.g. real next to generated), as MP4 "
                    "(H.264 + the first clip's sound as AAC) or as a PNG sequence."),
     {{QStringLiteral("media"), QStringLiteral("CLIP"), QStringLiteral("the clip"), {}, CommandOption::Required},
      {QStringLiteral("beside"), QStringLiteral("OTHER_CLIP"), QStringLiteral("a second clip, shown on the right")},
      {QStringLiteral("no-audio"), {}, QStringLiteral("export the picture only")}},
     {}}
        .add(VideoOutput::options()),
    &runExportVideo};

} // namespace
