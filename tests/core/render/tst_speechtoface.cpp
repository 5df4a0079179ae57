// Generation from new speech and rendering: a model trained on the demo project generates
// parameters for a demo clip from its sound and transcript; the faces are rendered into the clip
// (or onto a neutral frame for audio only) and exported with the sound. Bad input (no sound, a
// transcript that cannot fit, another AAM's model) fails naming the file; cancel leaves nothing
// under the final name.
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "render/VideoExporter.h"
#include "io/VideoReader.h"

#include "MediaProbe.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/AudioDecoder.h"
#include "io/WavWriter.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <functional>

using namespace lipsync;

namespace {

const std::string kDemo = std::string(LIPSYNC_SOURCE_DIR) + "/resources/demo";
const std::string kClip = kDemo + "/media/bbaf2n.mpg";
const std::string kTranscript = kDemo + "/media/bbaf2n.align";
const std::string kAam = kDemo + "/aam/demo.aam";
const std::string kAligner = std::string(LIPSYNC_SOURCE_DIR) + "/resources/aligner/grid-s1.aligner";

bool noHiddenFiles(const QString &folder)
{
    return QDir(folder).entryList(QDir::Hidden | QDir::Files | QDir::NoDotAndDotDot).filter(".part").isEmpty();
}

} // namespace

class TestSpeechToFace : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::string m_model;
    AamModel m_aam;

    SpeechToFaceRequest request(const std::string &media = kClip) const
    {
        SpeechToFaceRequest r;
        r.mediaPath = media;
        r.transcriptPath = kTranscript;
        r.modelPath = m_model;
        r.aamPath = kAam;
        r.aligner.model = kAligner;
        return r;
    }

    // request() generated as it is, and with `change` made to it.
    std::pair<SpeechToFaceResult, SpeechToFaceResult>
    generatedBothWays(const std::function<void(SpeechToFaceRequest &)> &change) const
    {
        Feedback feedback;
        SpeechToFaceRequest changed = request();
        change(changed);
        return {generateFromSpeech(request(), feedback), generateFromSpeech(changed, feedback)};
    }

private slots:
    // An HMM-mean model of the demo project's tracked features and phone tiers, for the demo AAM.
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_aam = AamModel::load(kAam);
        const Project project = Project::load(kDemo);
        std::vector<LabelledSequence> sequences;
        for (const Sequence &s : project.sequences) {
            if (s.features.rows() == 0 || s.phones.isEmpty())
                continue;
            sequences.push_back({s.id, frameLabelsFromTier(s.phones, s.frameRate, int(s.features.rows())), s.features});
        }
        QVERIFY(sequences.size() >= 5);
        auto model = createDynamicModel("hmm");
        Feedback feedback;
        model->train(sequences, feedback);
        QCOMPARE(model->dimension(), m_aam.combinedModes());
        m_model = m_dir.filePath("demo.model").toStdString();
        saveModel(*model, m_model, m_aam.identifier);
    }

    // The clip's own tracked parameters rendered back into it give the recording itself (its own
    // face, moved nowhere); other parameters move the lower face and nothing far from it; the
    // AAM's synthesis of the skin (synthesizeSkin) reproduces the face region closely and leaves
    // everything outside it untouched.
    void rendersTrackedFacesBackIntoTheClip()
    {
        Feedback feedback;
        FaceRenderer renderer(m_aam, kClip, feedback);
        QVERIFY(renderer.hasVideo());
        QCOMPARE(renderer.videoFrameCount(), 75);
        QCOMPARE(renderer.frameSize(), cv::Size(360, 288));
        QCOMPARE(renderer.trackedFeatures().rows(), Eigen::Index(75));
        const int i = 40;
        const cv::Mat real = renderer.background(i);
        const Eigen::VectorXd tracked = renderer.trackedFeatures().row(i).transpose();
        QCOMPARE(cv::norm(renderer.render(i, tracked), real, cv::NORM_INF), 0.0);
        // Another mouth: the lower face moves, the eyes and everything beyond the face stay.
        Eigen::VectorXd other = tracked;
        other[0] += 3.0 * std::sqrt(m_aam.combinedVariances[0]);
        cv::Mat diff, changed;
        cv::absdiff(real, renderer.render(i, other), diff);
        cv::cvtColor(diff, changed, cv::COLOR_BGR2GRAY);
        const cv::Rect moved = cv::boundingRect(changed > 2);
        QVERIFY2(moved.area() > 30 * 30, "the lower face moved");
        // The eyes (the box of their points) are the recording's.
        const Eigen::VectorXd points = renderer.trackedShape(i);
        double left = 1e9, right = 0, top = 1e9, bottom = 0;
        for (int k = 0; k < 8; ++k) {
            left = std::min(left, points[2 * k]);
            right = std::max(right, points[2 * k]);
            top = std::min(top, points[2 * k + 1]);
            bottom = std::max(bottom, points[2 * k + 1]);
        }
        const cv::Rect eyes(int(left) - 3, int(top) - 3, int(right - left) + 6, int(bottom - top) + 6);
        QVERIFY2(cv::countNonZero(changed(eyes) > 4) == 0, qPrintable(QString::number(cv::countNonZero(changed(eyes) > 4))));
        QVERIFY(moved.y < points[2 * 16 + 1]); // the mouth moved
        QCOMPARE(cv::countNonZero(changed(cv::Rect(0, 0, 40, 288))), 0);
        QCOMPARE(cv::countNonZero(changed(cv::Rect(320, 0, 40, 288))), 0);

        CompositeOptions skin;
        skin.synthesizeSkin = true;
        renderer.setCompositeOptions(skin);
        const cv::Mat rendered = renderer.render(i, tracked);
        cv::absdiff(real, rendered, diff);
        cv::cvtColor(diff, changed, cv::COLOR_BGR2GRAY);
        const cv::Rect face = cv::boundingRect(changed > 0);
        QVERIFY2(face.area() > 40 * 40, "the face region was drawn");
        QVERIFY2(face.area() < 360 * 288 / 2, "only the face region was drawn");
        const double meanError = cv::mean(diff(face))[0];
        QVERIFY2(meanError < 12.0, qPrintable(QString("mean difference %1 in the face box").arg(meanError)));
        // Other parameters give another face.
        cv::absdiff(rendered, renderer.render(i, other), diff);
        QVERIFY(cv::mean(diff(face))[0] > 1.0);
        renderer.setCompositeOptions({});
        // Wrong dimension: a clear error.
        QVERIFY_THROWS_EXCEPTION(Error, renderer.render(i, Eigen::VectorXd::Zero(3)));

        // A still of the person (Live): only the first frame is tracked and drawn into, the same
        // pixels and pose however often and whatever frame is asked for.
        FaceRenderer still(m_aam, kClip, feedback, nullptr, 1);
        QCOMPARE(still.videoFrameCount(), 1);
        QCOMPARE(still.trackedFeatures().rows(), Eigen::Index(1));
        QCOMPARE(still.trackedFeatures().row(0), renderer.trackedFeatures().row(0));
        const cv::Mat first = renderer.background(0);
        const Eigen::VectorXd params = renderer.trackedFeatures().row(i).transpose();
        const cv::Mat once = still.render(0, params);
        for (int k : {0, 12, 0, 74, 500}) {
            QCOMPARE(cv::norm(still.background(k), first, cv::NORM_INF), 0.0);
            QCOMPARE(cv::norm(still.render(k, params), once, cv::NORM_INF), 0.0);
        }
        QVERIFY(cv::norm(once, first, cv::NORM_INF) > 0.0);
    }

    // A hand over the mouth (a grey block over the lower face in frames 30-44): the tracker's fit
    // there is far worse than the clip's usual, and those frames are left as recorded; the others
    // are drawn into.
    void coveredMouthIsLeftAlone()
    {
        VideoReader clip(kClip);
        QTemporaryDir dir;
        const std::string covered = dir.filePath("covered.mp4").toStdString();
        {
            Feedback feedback;
            VideoExportOptions options;
            options.crf = 12;
            exportVideo(covered, clip.frameCount(), [&](int t) {
                cv::Mat frame = clip.frame(t);
                if (t >= 30 && t < 45)
                    cv::rectangle(frame, cv::Rect(120, 195, 120, 70), cv::Scalar(150, 160, 170), cv::FILLED);
                return frame;
            }, nullptr, feedback, options);
        }
        Feedback feedback;
        FaceRenderer renderer(m_aam, covered, feedback);
        int coveredFrames = 0, drawn = 0;
        for (int t = 0; t < renderer.videoFrameCount(); ++t) {
            Eigen::VectorXd other = renderer.trackedFeatures().row(t).transpose();
            other[0] += 3.0 * std::sqrt(m_aam.combinedVariances[0]);
            const bool same = cv::norm(renderer.render(t, other), renderer.background(t), cv::NORM_INF) == 0.0;
            if (t >= 30 && t < 45) {
                coveredFrames += renderer.occluded(t);
                if (renderer.occluded(t))
                    QVERIFY2(same, qPrintable(QString::number(t)));
            } else {
                // Blinks (frames 43-53 of this clip) fit 5-15 times worse than the median: not covered.
                QVERIFY2(!renderer.occluded(t), qPrintable(QString::number(t)));
                if (t >= 15 && t < 60)
                    drawn += !same;
            }
        }
        QVERIFY2(coveredFrames >= 12, qPrintable(QString("%1 of 15 covered frames found").arg(coveredFrames)));
        QVERIFY2(drawn >= 25, qPrintable(QString::number(drawn)));
    }

    // The rule on fit errors alone: a rare outlier is covered; wide-open mouths that an AAM of
    // few frames fits 30 times worse than the closed ones, in 60 % of a clip, are not.
    void coverIsARareOutlier()
    {
        Eigen::VectorXd errors = Eigen::VectorXd::Constant(100, 1.0);
        errors.segment(10, 15).setConstant(60.0); // a hand over the mouth
        errors[50] = NAN;                           // no face
        std::vector<bool> covered = FaceRenderer::occludedFrames(errors);
        QCOMPARE(int(std::count(covered.begin(), covered.end(), true)), 16);
        QVERIFY(covered[10] && covered[24] && covered[50] && !covered[25]);
        for (int t = 0; t < 100; ++t)
            errors[t] = t % 5 < 3 ? 30.0 : 1.0; // open, open, open, closed, closed
        covered = FaceRenderer::occludedFrames(errors);
        QCOMPARE(int(std::count(covered.begin(), covered.end(), true)), 0);
        errors[7] = 1000.0; // and one frame lost among them (over 25 times their median, 30)
        covered = FaceRenderer::occludedFrames(errors);
        QCOMPARE(int(std::count(covered.begin(), covered.end(), true)), 1);
        QVERIFY(covered[7]);
    }

    void neutralFrameWithoutVideo()
    {
        FaceRenderer renderer(m_aam);
        QVERIFY(!renderer.hasVideo());
        const cv::Mat mean = renderer.render(0, Eigen::VectorXd::Zero(m_aam.combinedModes()));
        QCOMPARE(mean.size(), cv::Size(360, 288));
        QCOMPARE(mean.at<cv::Vec3b>(2, 2), cv::Vec3b(128, 128, 128)); // background
        const cv::Vec3b centre = mean.at<cv::Vec3b>(144, 180);
        QVERIFY(centre != cv::Vec3b(128, 128, 128)); // the face is there
        // The whole mean face, eyes included (with no recording to keep the eyes from): the top of
        // the face (it fills the middle half of the frame's height) is not left grey.
        const cv::Mat background = renderer.background(0);
        int face = 0, all = 0;
        for (int r = 80; r < 110; ++r)
            for (int c = 150; c < 210; ++c, ++all)
                face += background.at<cv::Vec3b>(r, c) != cv::Vec3b(128, 128, 128);
        QVERIFY2(face > all * 3 / 4, qPrintable(QStringLiteral("%1 of %2").arg(face).arg(all)));
    }

    void generatesFromSpeechAndExports()
    {
        Feedback feedback;
        const SpeechToFaceResult result = generateFromSpeech(request(), feedback);
        QCOMPARE(result.frameCount(), 75);
        QCOMPARE(result.features.cols(), Eigen::Index(m_aam.combinedModes()));
        QCOMPARE(int(result.labels.size()), 75);
        QCOMPARE(result.frameRate, 25.0);
        QVERIFY(result.hasVideo);
        QCOMPARE(result.modelKind, std::string("hmm"));
        QVERIFY(result.phones.intervals.size() > 10);
        QVERIFY(std::abs(result.audio.duration() - 3.0) < 0.05);
        // Speech is not all silence: the labels hold phones.
        int speech = 0;
        for (int label : result.labels)
            speech += label != PhoneSet::kSilence;
        QVERIFY(speech > 30);

        auto renderer = makeRenderer(result, kClip, feedback);
        const QString out = m_dir.filePath("generated.mp4");
        const int written = exportRenderedVideo(result, *renderer, out.toStdString(), feedback);
        // The clip's own 75 frames at their own times, the sound (2.98 s) continued to their 3.0 s.
        QCOMPARE(written, 75);
        QCOMPARE(result.frames.count(), 75);
        const MediaProbe probe = MediaProbe::read(out.toStdString());
        QCOMPARE(probe.videoCodec, AV_CODEC_ID_H264);
        QCOMPARE(probe.audioCodec, AV_CODEC_ID_AAC);
        QCOMPARE(int(probe.frameTimes.size()), written);
        QVERIFY(std::abs(probe.videoDuration - probe.audioDuration) <= 1.0 / 25 + 1e-6);
        QVERIFY(!probe.audio.empty());

        // Side by side: twice as wide.
        RenderOptions side;
        side.sideBySide = true;
        const QString wide = m_dir.filePath("side.mp4");
        exportRenderedVideo(result, *renderer, wide.toStdString(), feedback, side);
        QCOMPARE(MediaProbe::read(wide.toStdString()).width, 720);

        // PNGs.
        const QString folder = m_dir.filePath("frames");
        QCOMPARE(int(exportRenderedImages(result, *renderer, folder.toStdString(), feedback).size()),
                 result.frameCount());
    }

    // A model trained at another rate (here 12.5 frames/s) generates at its own and is sampled at
    // the clip's 25: every odd frame lies half-way between its neighbours, also where the phone
    // (and so the HMM-mean's output) changes.
    void generatesAtTheModelsOwnRate()
    {
        std::shared_ptr<DynamicModel> model = loadModel(m_model);
        model->setFrameRate(12.5);
        SpeechToFaceRequest r = request();
        r.model = model;
        r.aam = std::make_shared<const AamModel>(m_aam);
        r.closeBilabials = false; // the model's own trajectory, sampled
        Feedback feedback;
        const SpeechToFaceResult result = generateFromSpeech(r, feedback);
        QCOMPARE(result.frameRate, 25.0);
        QCOMPARE(result.frameCount(), 75);
        QCOMPARE(int(result.labels.size()), 75);
        int halfWay = 0;
        for (int t = 1; t + 1 < 74; t += 2) {
            const Eigen::RowVectorXd mid = 0.5 * (result.features.row(t - 1) + result.features.row(t + 1));
            QVERIFY2((result.features.row(t) - mid).cwiseAbs().maxCoeff() < 1e-9, qPrintable(QString::number(t)));
            halfWay += (result.features.row(t) - result.features.row(t - 1)).cwiseAbs().maxCoeff() > 1e-6;
        }
        QVERIFY2(halfWay >= 5, qPrintable(QString::number(halfWay)));
    }

    // "bin blue": the generated lips close on the frames of the two /b/s (BilabialClosure), and
    // only there; without closure the model's own trajectory leaves them apart.
    void closesTheLipsOnBilabials()
    {
        const auto [closed, open] = generatedBothWays([](SpeechToFaceRequest &r) { r.closeBilabials = false; });
        QCOMPARE(closed.phones, open.phones);
        const BilabialClosure closure(m_aam);
        const std::vector<double> w = BilabialClosure::weights(closed.phones, closed.frames);
        int full = 0, wereOpen = 0;
        for (int t = 0; t < closed.frameCount(); ++t) {
            const Eigen::VectorXd c = closed.features.row(t).transpose(), g = open.features.row(t).transpose();
            if (w[size_t(t)] == 0.0) {
                QCOMPARE(c, g);
                continue;
            }
            if (w[size_t(t)] == 1.0) {
                ++full;
                QVERIFY2(closure.opening(c) < 1e-9, qPrintable(QString::number(t)));
                wereOpen += closure.opening(g) > 1e-3;
            }
        }
        QVERIFY2(full >= 2, qPrintable(QString::number(full)));
        QVERIFY2(wereOpen >= 1, qPrintable(QString::number(wereOpen)));
    }

    // The generated face keeps the clip's own posture (PostureTransfer) unless asked not to: the
    // model's trajectory is the same, the frames drawn differ, and the 23 points drawn lie nearer
    // the ones tracked there.
    void keepsTheClipsPosture()
    {
        const auto [kept, average] = generatedBothWays([](SpeechToFaceRequest &r) { r.keepPosture = false; });
        QVERIFY(kept.posture);
        Feedback feedback;
        QVERIFY(!average.posture);
        QCOMPARE(kept.features, average.features);
        auto renderer = makeRenderer(kept, kClip, feedback);
        const AamSynthesizer &synthesizer = renderer->synthesizer();
        double nearKept = 0, nearAverage = 0;
        int differ = 0;
        for (int t = 0; t < kept.frameCount(); t += 5) {
            const Eigen::VectorXd posture = renderer->posture(t);
            QCOMPARE(posture.size(), Eigen::Index(m_aam.combinedModes()));
            QVERIFY(posture.allFinite());
            const Eigen::VectorXd c = kept.features.row(t).transpose();
            const Eigen::VectorXd tracked = synthesizer.shape(renderer->trackedFeatures().row(t).transpose());
            nearKept += (synthesizer.shape(kept.posture->apply(c, posture)) - tracked).squaredNorm();
            nearAverage += (synthesizer.shape(c) - tracked).squaredNorm();
            differ += cv::norm(renderFrame(kept, *renderer, t, {}), renderFrame(average, *renderer, t, {}),
                               cv::NORM_INF) > 0;
        }
        QVERIFY2(nearKept < 0.8 * nearAverage, qPrintable(QStringLiteral("%1 %2").arg(nearKept).arg(nearAverage)));
        QVERIFY2(differ >= 10, qPrintable(QString::number(differ)));
    }

    void audioOnlyRendersOntoANeutralFrame()
    {
        const std::string wav = m_dir.filePath("speech.wav").toStdString();
        const AudioBuffer sound = AudioDecoder::decode(kClip, 16000);
        writeWav(wav, sound.samples, 0, sound.samples.size(), sound.sampleRate); // no video stream
        Feedback feedback;
        const QString out = m_dir.filePath("audio-only.mp4");
        const SpeechVideoReport report = renderSpeechVideo(request(wav), out.toStdString(), feedback);
        QVERIFY(!report.generated.hasVideo);
        // Frames every 1/25 s from the sound's start until it has ended.
        QCOMPARE(report.generated.frameCount(), int(std::ceil(report.generated.audio.duration() * 25 - 1e-6)));
        const MediaProbe probe = MediaProbe::read(out.toStdString());
        QCOMPARE(int(probe.frameTimes.size()), report.framesWritten);
        QCOMPARE(probe.width, 360);
        // Side by side needs a real video.
        RenderOptions side;
        side.sideBySide = true;
        FaceRenderer neutral(m_aam);
        QVERIFY_THROWS_EXCEPTION(Error, exportRenderedVideo(report.generated, neutral,
                                                            m_dir.filePath("x.mp4").toStdString(), feedback, side));
    }

    void cancelLeavesNoFile()
    {
        Feedback feedback;
        const SpeechToFaceResult result = generateFromSpeech(request(), feedback);
        auto renderer = makeRenderer(result, kClip, feedback);
        const QString folder = m_dir.filePath("cancel");
        QVERIFY(QDir().mkpath(folder));
        const QString out = folder + "/canceled.mp4";
        Feedback canceling;
        canceling.onProgress = [&](double p) {
            if (p > 0.3)
                canceling.cancel();
        };
        QVERIFY_THROWS_EXCEPTION(Canceled, exportRenderedVideo(result, *renderer, out.toStdString(), canceling));
        QVERIFY(!QFile::exists(out));
        QVERIFY(noHiddenFiles(folder));
    }

    void badInputNamesTheFile()
    {
        Feedback feedback;
        // Media without sound.
        const std::string silent = std::string(LIPSYNC_TEST_DATA) + "/media/no_audio_29.97fps.mp4";
        try {
            generateFromSpeech(request(silent), feedback);
            QFAIL("no error for media without audio");
        } catch (const Error &e) {
            QCOMPARE(e.file(), silent);
            QVERIFY(std::string(e.what()).find("no audio stream") != std::string::npos);
        }
        // A transcript far too long for three seconds of speech.
        const QString longText = m_dir.filePath("long.txt");
        {
            QFile f(longText);
            QVERIFY(f.open(QIODevice::WriteOnly));
            for (int i = 0; i < 40; ++i)
                f.write("place blue at seven again please ");
        }
        SpeechToFaceRequest r = request();
        r.transcriptPath = longText.toStdString();
        try {
            generateFromSpeech(r, feedback);
            QFAIL("no error for a transcript that does not fit");
        } catch (const Error &e) {
            QVERIFY2(std::string(e.what()).find(longText.toStdString()) != std::string::npos, e.what());
        }
        // A model trained for another AAM.
        const std::string otherModel = m_dir.filePath("other.model").toStdString();
        saveModel(*loadModel(m_model), otherModel, "another-aam");
        r = request();
        r.modelPath = otherModel;
        try {
            generateFromSpeech(r, feedback);
            QFAIL("no error for another AAM's model");
        } catch (const Error &e) {
            QCOMPARE(e.file(), otherModel);
        }
    }
};

QTEST_GUILESS_MAIN(TestSpeechToFace)
#include "tst_speechtoface.moc"
