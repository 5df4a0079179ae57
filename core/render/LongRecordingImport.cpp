#include "render/LongRecordingImport.h"

#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/VideoReader.h"
#include "io/WavWriter.h"
#include "project/Project.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <cmath>
#include <cstdio>
#include <set>

namespace lipsync {

namespace {

// The sound the clips get: mono at the aligner's rate.
constexpr int kClipSampleRate = 16000;
// Share of the progress bar the alignment takes; writing the clips takes the rest.
constexpr double kAligningShare = 0.3;

std::string numbered(const std::string &stem, size_t index)
{
    char suffix[24];
    std::snprintf(suffix, sizeof suffix, "_%04zu", index + 1);
    return stem + suffix;
}

} // namespace

LongRecordingImportResult importLongRecording(const Project &project, const std::string &mediaPath,
                                              const std::vector<std::string> &words,
                                              const std::string &transcriptPath, const Aligner &aligner,
                                              const Lexicon &lexicon, const LongRecordingImportOptions &options,
                                              Feedback *feedback)
{
    const MediaInfo info = MediaInfo::probe(mediaPath);
    if (!info.hasAudio)
        throw Error("no audio stream", mediaPath);
    AlignerOutput aligned;
    {
        Feedback dummy;
        Feedback part(feedback ? *feedback : dummy, 0.0, kAligningShare);
        aligned = aligner.align(mediaPath, words, lexicon, &part, transcriptPath);
    }

    // The alignment, the sound and the frames share the media timeline: the clips are cut at frame
    // boundaries, and each clip's times start from 0 at its first frame.
    const AudioBuffer audio = AudioDecoder::decode(mediaPath, kClipSampleRate);
    std::unique_ptr<VideoReader> video;
    UtteranceSplitOptions split = options.split;
    if (info.hasVideo) {
        video = std::make_unique<VideoReader>(mediaPath);
        split.frames = video->clock();
    } else {
        split.frames = FrameClock::uniform(Project::kAudioOnlyFrameRate,
                                           int(std::ceil(audio.duration() * Project::kAudioOnlyFrameRate - 1e-9)));
    }
    const FrameClock &clock = split.frames;
    const std::vector<UtteranceSpan> spans = splitAtPauses(aligned.alignment.words, aligned.alignment.phones,
                                                           clock.endTime(), split);

    const std::string stem = QFileInfo(QString::fromStdString(mediaPath)).completeBaseName().toStdString();
    std::set<std::string> taken;
    for (const Sequence &s : project.sequences)
        taken.insert(s.id);
    for (size_t k = 0; k < spans.size(); ++k)
        if (taken.count(numbered(stem, k)))
            throw Error("the project already has a sequence " + numbered(stem, k)
                            + " (was this recording imported before?)",
                        mediaPath);
    const QDir projectDir(QString::fromStdString(project.folder().empty() ? "." : project.folder()));
    const QString clipDir = projectDir.filePath(QString::fromStdString(options.clipFolder));
    if (!QDir().mkpath(clipDir))
        throw Error("cannot create the clip folder", clipDir.toStdString());

    LongRecordingImportResult result;
    result.duration = aligned.duration;
    std::vector<QString> written;
    try {
        Feedback dummy;
        Feedback part(feedback ? *feedback : dummy, kAligningShare, 1.0);
        for (size_t k = 0; k < spans.size(); ++k) {
            part.throwIfCanceled();
            part.setProgress(double(k) / double(spans.size()));
            const UtteranceSpan &span = spans[k];
            Sequence s;
            s.id = numbered(stem, k);
            const int firstFrame = std::min(clock.frameAtBoundary(span.start), clock.count() - 1);
            const int endFrame = std::max(firstFrame + 1, clock.frameAtBoundary(span.end));
            // The clip's own file starts at its first frame.
            const FrameClock clipClock = clock.slice(firstFrame, endFrame - firstFrame).shifted(-clock.time(firstFrame));
            s.setClock(clipClock);
            const double from = clock.time(firstFrame);
            const size_t begin = std::min(audio.samples.size(), size_t(std::llround(from * kClipSampleRate)));
            const size_t end = std::min(audio.samples.size(),
                                        begin + size_t(std::llround(clipClock.endTime() * kClipSampleRate)));
            const QString file = QDir(clipDir).filePath(QString::fromStdString(s.id) + (video ? ".mp4" : ".wav"));
            if (video) {
                AudioBuffer clipAudio;
                clipAudio.sampleRate = kClipSampleRate;
                clipAudio.samples.assign(audio.samples.begin() + long(begin), audio.samples.begin() + long(end));
                if (clipAudio.samples.empty())
                    clipAudio.samples.assign(1, 0.0f); // a clip past the end of the sound: silence
                VideoExportOptions v;
                v.setFrames(clipClock);
                v.crf = options.crf;
                VideoExporter exporter(file.toStdString(), v, &clipAudio);
                for (int f = firstFrame; f < endFrame; ++f)
                    exporter.addFrame(video->frame(f));
                exporter.finish();
            } else {
                writeWav(file.toStdString(), audio.samples, begin, end, kClipSampleRate);
            }
            written.push_back(file);
            s.mediaFile = projectDir.relativeFilePath(file).toStdString();
            s.transcript = span.transcript;
            s.words = span.words;
            s.phones = span.phones;
            for (const Interval &i : span.words.intervals)
                result.words += PhoneSet::isSilence(i.label) ? 0 : 1;
            result.spokenSeconds += span.end - span.start;
            result.sequences.push_back(std::move(s));
        }
    } catch (...) {
        for (const QString &file : written)
            QFile::remove(file);
        throw;
    }
    if (feedback)
        feedback->setProgress(1.0);
    return result;
}

} // namespace lipsync
