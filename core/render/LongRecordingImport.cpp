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
                                              Feedback &feedback)
{
    const MediaInfo info = MediaInfo::probe(mediaPath);
    if (!info.hasAudio)
        throw Error("no audio stream", mediaPath);
    AlignerOutput aligned;
    {
        Feedback part(feedback, 0.0, kAligningShare);
        aligned = aligner.align(mediaPath, words, lexicon, part, transcriptPath);
    }

    // The alignment, the sound and the frames share the media timeline: the clips are cut at frame
    // boundaries, and each clip's times start from 0 at its first frame.
    std::unique_ptr<VideoReader> video;
    UtteranceSplitOptions split = options.split;
    if (info.hasVideo) {
        video = std::make_unique<VideoReader>(mediaPath);
        split.frames = video->clock();
    } else {
        split.frames = FrameClock::uniform(Project::kAudioOnlyFrameRate,
                                           int(std::ceil(info.audioEndTime * Project::kAudioOnlyFrameRate - 1e-9)));
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

    // Each clip's frames and the stretch of the sound they show.
    struct Clip
    {
        int firstFrame = 0, endFrame = 0;
        FrameClock clock; // its own times, from 0
    };
    std::vector<Clip> clips;
    std::vector<std::pair<double, double>> sound;
    for (const UtteranceSpan &span : spans) {
        Clip c;
        c.firstFrame = std::min(clock.frameAtBoundary(span.start), clock.count() - 1);
        c.endFrame = std::max(c.firstFrame + 1, clock.frameAtBoundary(span.end));
        c.clock = clock.slice(c.firstFrame, c.endFrame - c.firstFrame).shifted(-clock.time(c.firstFrame));
        sound.emplace_back(clock.time(c.firstFrame), clock.time(c.firstFrame) + c.clock.endTime());
        clips.push_back(std::move(c));
    }

    LongRecordingImportResult result;
    result.duration = aligned.duration;
    result.transcriptFit = aligned.transcriptFit;
    std::vector<QString> written;
    try {
        Feedback part(feedback, kAligningShare, 1.0);
        // One pass over the sound at its own rate, each clip's stretch handed over as the decoding
        // reaches its end: memory for one clip's sound, not the recording's.
        AudioDecoder::decodeRanges(mediaPath, 0, sound, [&](size_t k, AudioBuffer clipAudio) {
            part.throwIfCanceled();
            part.setProgress(double(k) / double(spans.size()));
            const UtteranceSpan &span = spans[k];
            const Clip &clip = clips[k];
            Sequence s;
            s.id = numbered(stem, k);
            s.setClock(clip.clock);
            if (clipAudio.samples.empty())
                clipAudio.samples.assign(1, 0.0f); // a clip past the end of the sound: silence
            clipAudio.startTime = 0.0;
            const QString file = QDir(clipDir).filePath(QString::fromStdString(s.id) + (video ? ".mp4" : ".wav"));
            if (video) {
                VideoExportOptions v;
                v.setFrames(clip.clock);
                v.crf = options.crf;
                VideoExporter exporter(file.toStdString(), v, &clipAudio);
                for (int f = clip.firstFrame; f < clip.endFrame; ++f)
                    exporter.addFrame(video->frame(f));
                exporter.finish();
            } else {
                writeWav(file.toStdString(), clipAudio.samples, 0, clipAudio.samples.size(), clipAudio.sampleRate);
            }
            written.push_back(file);
            s.mediaFile = projectDir.relativeFilePath(file).toStdString();
            s.transcript = span.transcript;
            s.words = span.words;
            s.phones = span.phones;
            s.transcriptFit = aligned.transcriptFit;
            for (const Interval &i : span.words.intervals)
                result.words += PhoneSet::isSilence(i.label) ? 0 : 1;
            result.spokenSeconds += span.end - span.start;
            result.sequences.push_back(std::move(s));
        });
    } catch (...) {
        for (const QString &file : written)
            QFile::remove(file);
        throw;
    }
    feedback.setProgress(1.0);
    return result;
}

} // namespace lipsync
