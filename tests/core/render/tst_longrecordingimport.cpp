// A long recording into a project as utterance sequences (render/LongRecordingImport.h), on the
// GRID demo clips put back to back — as sound alone (a WAV written by io/WavWriter, whose round
// trip is checked first) and as a video (an MP4 written by VideoExporter):
//  - one sequence per sentence, its clip in PROJECT/clips, as long as its frames say, its words
//    those of the transcript in order and its tiers tiling the clip;
//  - a video's clips hold the recording's frames (the same picture, re-encoded);
//  - cancel leaves no clip behind; importing the same recording again is an Error naming it.
#include "align/Aligner.h"
#include "align/Lexicon.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "io/VideoReader.h"
#include "io/WavWriter.h"
#include "project/Project.h"
#include "render/LongRecordingImport.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

#include <opencv2/core.hpp>

#include <cmath>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";
const std::string kShippedModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";
const char *const kClips[] = {"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p",
                              "pbav2n", "pgwe6n", "pwbk1s", "sbwo1s", "srbu6n"};

std::vector<std::string> demoWords(int clips)
{
    std::vector<std::string> words;
    for (int c = 0; c < clips; ++c)
        for (const std::string &w : readTranscript(kDemo + kClips[c] + ".align").words)
            words.push_back(w);
    return words;
}

std::vector<float> demoSound(int clips)
{
    std::vector<float> samples;
    for (int c = 0; c < clips; ++c) {
        const AudioBuffer a = AudioDecoder::decode(kDemo + kClips[c] + ".mpg", 16000);
        samples.insert(samples.end(), a.samples.begin(), a.samples.end());
    }
    return samples;
}

double rms(const std::vector<float> &samples)
{
    double sum = 0;
    for (float v : samples)
        sum += double(v) * v;
    return samples.empty() ? 0.0 : std::sqrt(sum / double(samples.size()));
}

Project emptyProject(const QString &folder)
{
    Project p;
    p.setFolder(folder.toStdString());
    p.name = "long";
    return p;
}

LongRecordingImportOptions sentenceOptions()
{
    LongRecordingImportOptions o;
    o.split.shortest = 1.0; // a GRID sentence lasts about 1.8 s
    return o;
}

// Checks the imported sequences against the transcript; returns their clips' paths.
QStringList checkSequences(const Project &project, const std::vector<std::string> &words, const QString &suffix)
{
    QStringList files;
    std::vector<std::string> said;
    for (const Sequence &s : project.sequences) {
        const MediaInfo info = MediaInfo::probe(project.mediaPath(s));
        files << QString::fromStdString(project.mediaPath(s));
        [&] {
            QVERIFY2(QString::fromStdString(s.mediaFile).startsWith(QStringLiteral("clips/")), s.mediaFile.c_str());
            QVERIFY(QString::fromStdString(s.mediaFile).endsWith(suffix));
            QCOMPARE(s.frameRate, 25.0);
            QVERIFY(s.frameCount > 25);
            if (info.hasVideo)
                QCOMPARE(info.frameCount, s.frameCount);
            QVERIFY2(std::abs(info.audioDuration - s.duration()) < 0.06,
                     qPrintable(QStringLiteral("%1 vs %2").arg(info.audioDuration).arg(s.duration())));
            QCOMPARE(s.words.intervals.front().start, 0.0);
            QVERIFY(std::abs(s.words.intervals.back().end - s.duration()) < 1e-6);
            QVERIFY(std::abs(s.phones.intervals.back().end - s.duration()) < 1e-6);
            for (size_t i = 1; i < s.phones.intervals.size(); ++i)
                QCOMPARE(s.phones.intervals[i].start, s.phones.intervals[i - 1].end);
        }();
        std::vector<std::string> own;
        for (const Interval &i : s.words.intervals)
            if (!PhoneSet::isSilence(i.label))
                own.push_back(i.label);
        [&] { QCOMPARE(parsePlainTranscript(s.transcript).words, own); }();
        said.insert(said.end(), own.begin(), own.end());
    }
    [&] { QCOMPARE(said, words); }();
    return files;
}

} // namespace

class TestLongRecordingImport : public QObject
{
    Q_OBJECT
private slots:
    void wavRoundTrip()
    {
        QTemporaryDir dir;
        const std::vector<float> samples = demoSound(1);
        const std::string path = dir.filePath(QStringLiteral("one.wav")).toStdString();
        writeWav(path, samples, 1000, samples.size(), 16000);
        const AudioBuffer back = AudioDecoder::decode(path, 0);
        QCOMPARE(back.sampleRate, 16000);
        QCOMPARE(back.samples.size(), samples.size() - 1000);
        float worst = 0;
        for (size_t i = 0; i < back.samples.size(); ++i)
            worst = std::max(worst, std::abs(back.samples[i] - samples[i + 1000]));
        QVERIFY2(worst <= 1.5f / 32767.0f, // 16 bits each way, scaled by 32767 and back by 32768
                 qPrintable(QString::number(worst)));
        QVERIFY(std::abs(MediaInfo::probe(path).audioDuration - (samples.size() - 1000) / 16000.0) < 1e-9);
        // Under a file instead of a folder: an Error naming it.
        try {
            writeWav(path + "/x.wav", samples, 0, 10, 16000);
            QFAIL("wrote under a file");
        } catch (const Error &e) {
            QCOMPARE(e.file(), path + "/x.wav");
        }
    }

    void soundOnly()
    {
        QTemporaryDir dir;
        const std::vector<float> samples = demoSound(10);
        const QString wav = dir.filePath(QStringLiteral("talk.wav"));
        writeWav(wav.toStdString(), samples, 0, samples.size(), 16000);
        const std::vector<std::string> words = demoWords(10);
        Project project = emptyProject(dir.filePath(QStringLiteral("project")));
        const std::unique_ptr<Aligner> aligner = createAligner(AlignerChoice{kShippedModel, false});
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        Feedback feedback;
        double last = 0;
        feedback.onProgress = [&](double p) { last = p; };
        LongRecordingImportResult r = importLongRecording(project, wav.toStdString(), words, {}, *aligner, lexicon,
                                                          sentenceOptions(), feedback);
        QCOMPARE(last, 1.0);
        QCOMPARE(int(r.sequences.size()), 10);
        QCOMPARE(r.sequences.front().id, std::string("talk_0001"));
        project.sequences = std::move(r.sequences);
        QCOMPARE(r.words, int(words.size()));
        QCOMPARE(int(project.sequences.size()), 10);
        checkSequences(project, words, QStringLiteral(".wav"));
        // A sentence's clip holds that sentence's sound.
        QCOMPARE(project.sequences[3].transcript, readTranscript(kDemo + kClips[3] + ".align").text());

        // Again into the same project: refused.
        try {
            importLongRecording(project, wav.toStdString(), words, {}, *aligner, lexicon, sentenceOptions());
            QFAIL("imported twice");
        } catch (const Error &e) {
            QCOMPARE(e.file(), wav.toStdString());
            QVERIFY2(e.reason().find("already has a sequence talk_0001") != std::string::npos, e.what());
        }
    }

    // Asked for, the whole transcript's fit to the sound comes with the import and with each
    // utterance (the studio marks them): the recording's own words fit, the same words in another
    // order of its sentences do not.
    void transcriptFitCarried()
    {
        QTemporaryDir dir;
        const std::vector<float> samples = demoSound(4);
        const QString wav = dir.filePath(QStringLiteral("talk.wav"));
        writeWav(wav.toStdString(), samples, 0, samples.size(), 16000);
        AlignerChoice choice{kShippedModel, false};
        choice.transcriptFit = true;
        const std::unique_ptr<Aligner> aligner = createAligner(choice);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const LongRecordingImportResult own = importLongRecording(
            emptyProject(dir.filePath(QStringLiteral("own"))), wav.toStdString(), demoWords(4), {}, *aligner, lexicon,
            sentenceOptions());
        QVERIFY(own.transcriptFit && !own.transcriptFit->misfit());
        QCOMPARE(own.transcriptFit->threshold, kTranscriptFitThreshold);
        for (const Sequence &s : own.sequences)
            QCOMPARE(s.transcriptFit, own.transcriptFit);
        std::vector<std::string> shuffled;
        for (int c : {2, 0, 3, 1})
            for (const std::string &w : readTranscript(kDemo + kClips[c] + ".align").words)
                shuffled.push_back(w);
        const LongRecordingImportResult other = importLongRecording(
            emptyProject(dir.filePath(QStringLiteral("other"))), wav.toStdString(), shuffled, {}, *aligner, lexicon,
            sentenceOptions());
        QVERIFY(other.transcriptFit && other.transcriptFit->misfit());
        QVERIFY(!other.sequences.empty() && other.sequences.front().transcriptFit == other.transcriptFit);
        // Not asked for: none.
        const std::unique_ptr<Aligner> unmeasured = createAligner(AlignerChoice{kShippedModel, false});
        QVERIFY(!importLongRecording(emptyProject(dir.filePath(QStringLiteral("plain"))), wav.toStdString(),
                                     demoWords(4), {}, *unmeasured, lexicon, sentenceOptions())
                     .transcriptFit);
    }

    void cancelLeavesNothing()
    {
        QTemporaryDir dir;
        const std::vector<float> samples = demoSound(4);
        const QString wav = dir.filePath(QStringLiteral("talk.wav"));
        writeWav(wav.toStdString(), samples, 0, samples.size(), 16000);
        Project project = emptyProject(dir.filePath(QStringLiteral("project")));
        const std::unique_ptr<Aligner> aligner = createAligner(AlignerChoice{kShippedModel, false});
        Feedback feedback;
        feedback.onProgress = [&](double p) {
            if (p > 0.6)
                feedback.cancel();
        };
        QVERIFY_THROWS_EXCEPTION(Canceled, importLongRecording(project, wav.toStdString(), demoWords(4), {}, *aligner,
                                                               Lexicon(&PronunciationDictionary::cmu()),
                                                               sentenceOptions(), feedback));
        QVERIFY(QDir(dir.filePath(QStringLiteral("project/clips"))).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }

    // The clips carry the recording's sound at its own rate (GRID's 44.1 kHz), the stretch of
    // each clip exactly: no resampling for the aligner's sake.
    void clipsKeepTheRecordingsSoundRate()
    {
        QTemporaryDir dir;
        const std::string clip = kDemo + kClips[0] + ".mpg";
        Project project = emptyProject(dir.filePath(QStringLiteral("project")));
        const std::unique_ptr<Aligner> aligner = createAligner(AlignerChoice{kShippedModel, false});
        project.sequences = importLongRecording(project, clip, demoWords(1), {}, *aligner,
                                                Lexicon(&PronunciationDictionary::cmu()), sentenceOptions())
                                .sequences;
        QCOMPARE(int(project.sequences.size()), 1);
        const Sequence &s = project.sequences[0];
        QCOMPARE(MediaInfo::probe(clip).audioSampleRate, 44100);
        QCOMPARE(MediaInfo::probe(project.mediaPath(s)).audioSampleRate, 44100);
        const AudioBuffer source = AudioDecoder::decode(clip, 0), cut = AudioDecoder::decode(project.mediaPath(s), 0);
        QCOMPARE(cut.sampleRate, 44100);
        QVERIFY2(std::abs(cut.duration() - s.duration()) < 0.05, qPrintable(QString::number(cut.duration())));
        QVERIFY(std::abs(rms(cut.samples) - rms(source.samples)) < 0.5 * rms(source.samples)); // the speech, not silence
    }

    void video()
    {
        QTemporaryDir dir;
        constexpr int kClipsInVideo = 3;
        const QString mp4 = dir.filePath(QStringLiteral("show.mp4"));
        std::vector<cv::Mat> frames;
        {
            AudioBuffer sound;
            sound.sampleRate = 16000;
            sound.samples = demoSound(kClipsInVideo);
            VideoExportOptions options;
            options.crf = 12;
            VideoExporter exporter(mp4.toStdString(), options, &sound);
            for (int c = 0; c < kClipsInVideo; ++c) {
                VideoReader reader(kDemo + kClips[c] + ".mpg");
                for (int f = 0; f < reader.frameCount(); ++f)
                    frames.push_back(reader.frame(f).clone());
            }
            for (const cv::Mat &frame : frames)
                exporter.addFrame(frame);
            exporter.finish();
        }
        Project project = emptyProject(dir.filePath(QStringLiteral("project")));
        const std::unique_ptr<Aligner> aligner = createAligner(AlignerChoice{kShippedModel, false});
        const std::vector<std::string> words = demoWords(kClipsInVideo);
        project.sequences = importLongRecording(project, mp4.toStdString(), words, {}, *aligner,
                                                Lexicon(&PronunciationDictionary::cmu()), sentenceOptions())
                                .sequences;
        QCOMPARE(int(project.sequences.size()), kClipsInVideo);
        checkSequences(project, words, QStringLiteral(".mp4"));
        // The second clip's middle frame is a frame of the second sentence in the recording.
        const Sequence &s = project.sequences[1];
        VideoReader clip(project.mediaPath(s));
        const int f = s.frameCount / 2;
        VideoReader source(mp4.toStdString());
        double bestError = 1e9;
        int bestFrame = -1;
        const cv::Mat picture = clip.frame(f);
        for (int g = 0; g < source.frameCount(); ++g) {
            const double error = cv::norm(picture, source.frame(g), cv::NORM_L1) / double(picture.total() * 3);
            if (error < bestError) {
                bestError = error;
                bestFrame = g;
            }
        }
        QVERIFY2(bestError < 4.0, qPrintable(QString::number(bestError)));
        QVERIFY(bestFrame >= 75 && bestFrame < 150);
    }
};

QTEST_GUILESS_MAIN(TestLongRecordingImport)
#include "tst_longrecordingimport.moc"
