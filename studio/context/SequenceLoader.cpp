#include "context/SequenceLoader.h"

#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/VideoReader.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QCoreApplication>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace lipsync::studio {

namespace {

QImage toImage(const cv::Mat &bgr, double scale)
{
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    if (scale < 1.0)
        cv::resize(rgb, rgb, cv::Size(), scale, scale, cv::INTER_AREA);
    // Deep copy: the QImage must own its pixels once the cv::Mat goes away.
    return QImage(rgb.data, rgb.cols, rgb.rows, int(rgb.step), QImage::Format_RGB888).copy();
}

// Sample k of the decoded sound plays at k / sampleRate on the media timeline (AudioDecoder).
QVector<double> rmsPerFrame(const std::vector<float> &samples, int sampleRate, const FrameClock &clock)
{
    const int frames = clock.count();
    QVector<double> rms(frames, 0.0);
    for (int f = 0; f < frames; ++f) {
        const auto first = std::min(samples.size(), std::size_t(std::max(0LL, std::llround(clock.time(f) * sampleRate))));
        const auto last = std::min(samples.size(), std::size_t(std::max(0LL, std::llround(clock.endTime(f) * sampleRate))));
        double sum = 0.0;
        for (std::size_t i = first; i < last; ++i)
            sum += double(samples[i]) * samples[i];
        rms[f] = last > first ? std::sqrt(sum / double(last - first)) : 0.0;
    }
    return rms;
}

void decodeAudio(SequenceMedia &media, Feedback &feedback)
{
    feedback.setStatus(QCoreApplication::translate("SequenceLoader", "Decoding audio").toStdString());
    try {
        AudioBuffer audio = AudioDecoder::decode(media.mediaPath.toStdString(), SequenceLoader::kAudioRate);
        feedback.throwIfCanceled();
        media.spectrogram = std::make_shared<Spectrogram>(Spectrogram::compute(audio.samples, audio.sampleRate));
        media.peaks = std::make_shared<WaveformPeaks>(std::move(audio.samples), audio.sampleRate);
    } catch (const Error &e) {
        // A video without sound is still worth annotating: show the reason instead of a waveform.
        media.audioError = QString::fromStdString(e.reason());
    }
    feedback.setProgress(1.0);
}

void decodeVideo(SequenceMedia &media, Feedback &feedback)
{
    const std::string path = media.mediaPath.toStdString();
    if (!MediaInfo::probe(path).hasVideo) {
        // Sound alone (a WAV, an interview's audio track): frames of nothing at the sequence's
        // rate, so the timeline, the alignment and generated faces work as for a video.
        if (!media.peaks)
            throw Error("neither a video stream nor readable sound (" + media.audioError.toStdString() + ")", path);
        const double seconds = double(media.peaks->samples().size()) / media.peaks->sampleRate();
        const int count = std::max(1, int(std::lround(seconds * media.frameRate)));
        media.frames = QVector<QImage>(count);
        media.clock = FrameClock::uniform(media.frameRate, count);
        media.audioOnly = true;
        feedback.setProgress(1.0);
        return;
    }
    feedback.setStatus(QCoreApplication::translate("SequenceLoader", "Reading video frames").toStdString());
    VideoReader reader(path);
    if (reader.frameRate() > 0)
        media.frameRate = reader.frameRate();
    media.clock = reader.clock();
    const int count = reader.frameCount();
    const double bytes = double(count) * reader.width() * reader.height() * 4.0;
    const double scale = bytes > double(SequenceLoader::kFrameBudgetBytes)
                             ? std::sqrt(double(SequenceLoader::kFrameBudgetBytes) / bytes)
                             : 1.0;
    const double thumbScale = reader.height() > 0 ? double(SequenceLoader::kThumbnailHeight) / reader.height() : 1.0;
    media.frames.reserve(count);
    media.thumbnails.reserve(count);
    for (int i = 0; i < count; ++i) {
        feedback.throwIfCanceled();
        const cv::Mat frame = reader.frame(i);
        media.frames.append(toImage(frame, scale));
        media.thumbnails.append(toImage(frame, thumbScale));
        feedback.setProgress(double(i + 1) / count);
    }
}

} // namespace

Task *SequenceLoader::start(TaskRunner &runner, const SequenceSource &source, Apply apply)
{
    const QString title = QCoreApplication::translate("SequenceLoader", "Loading %1").arg(source.id);
    return runner.start(title, [source, apply = std::move(apply)](Feedback &feedback) -> TaskRunner::Commit {
        auto media = std::make_shared<SequenceMedia>();
        media->sequenceId = source.id;
        media->mediaPath = source.mediaPath;
        media->frameRate = source.frameRate;
        {
            Feedback audioPart(feedback, 0.0, 0.2);
            decodeAudio(*media, audioPart);
        }
        feedback.throwIfCanceled();
        {
            Feedback videoPart(feedback, 0.2, 1.0);
            decodeVideo(*media, videoPart);
        }
        if (media->peaks)
            media->frameRms = rmsPerFrame(media->peaks->samples(), media->peaks->sampleRate(), media->clock);
        return [apply, media] { apply(media); };
    });
}

} // namespace lipsync::studio
