// Speech to a face as the sound comes in (render/LiveSession.h), on a GRID demo clip fed in 10 ms
// blocks with the shipped aligner model and phone bigram and an HMM-mean and a DPDS model of the
// demo project:
//  - one frame per 1/25 s of sound, in order, each handed out once the sound up to its end and
//    the recogniser's look-ahead has come in, and no later than the session's latency after;
//  - the frames' phones are the §0 vote over the recognised phones, and their features what the
//    model generates for those phones at once (exactly, for the recursive models);
//  - with a renderer every frame is drawn; a model for another AAM is refused.
#include "aam/AamModel.h"
#include "align/AcousticModel.h"
#include "align/FrameLabels.h"
#include "align/PhoneBigram.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/LabelledFolder.h"
#include "dynamics/ModelFile.h"
#include "io/AudioDecoder.h"
#include "project/Project.h"
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/LiveSession.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <cmath>
#include <map>
#include <memory>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";

struct Fed
{
    std::vector<LiveFrame> frames;
    std::vector<double> fedWhenReady; // seconds of sound fed when each frame came out
};

Fed feed(LiveSession &session, const std::vector<float> &samples, size_t block = 160)
{
    Fed out;
    for (size_t at = 0; at < samples.size(); at += block) {
        const size_t n = std::min(block, samples.size() - at);
        for (LiveFrame &f : session.push(samples.data() + at, n)) {
            out.frames.push_back(std::move(f));
            out.fedWhenReady.push_back(double(at + n) / 16000.0);
        }
    }
    for (LiveFrame &f : session.finish()) {
        out.frames.push_back(std::move(f));
        out.fedWhenReady.push_back(INFINITY);
    }
    return out;
}

} // namespace

class TestLiveSession : public QObject
{
    Q_OBJECT
private:
    AcousticModel m_acoustic;
    PhoneBigram m_bigram;
    AamModel m_aam;
    std::vector<LabelledSequence> m_training;
    std::vector<float> m_sound;
    std::map<std::string, std::unique_ptr<DynamicModel>> m_models; // trained()

private slots:
    void initTestCase()
    {
        m_acoustic = AcousticModel::load(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner");
        m_bigram = PhoneBigram::load(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.bigram");
        m_aam = AamModel::load(kDemo + "/aam/demo.aam");
        m_training = loadProjectSequences(Project::load(kDemo));
        m_sound = AudioDecoder::decode(kDemo + "/media/lrik4p.mpg", 16000).samples;
    }

    void framesInTimeAndAsGenerated_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::newRow("dpds") << QStringLiteral("dpds");
        QTest::newRow("hmm") << QStringLiteral("hmm");
    }

    void framesInTimeAndAsGenerated()
    {
        QFETCH(QString, kind);
        const DynamicModel *model = trained(kind.toStdString());
        QCOMPARE(model->frameRate(), 25.0);
        LiveSession session(m_acoustic, m_bigram, *model, nullptr);
        QCOMPARE(session.frameRate(), 25.0);
        const Fed fed = feed(session, m_sound);
        const int expected = int(std::lround(m_sound.size() / 16000.0 * 25));
        QCOMPARE(int(fed.frames.size()), expected);
        const double lookAhead = 4 * 0.01 + 0.0125; // deltas' statics and half a window
        for (size_t i = 0; i < fed.frames.size(); ++i) {
            const LiveFrame &f = fed.frames[i];
            QCOMPARE(f.index, int(i));
            QVERIFY(std::abs(f.soundEnd - (i + 1) / 25.0) < 1e-12);
            QVERIFY(f.image.empty());
            if (std::isfinite(fed.fedWhenReady[i])) {
                const double waited = fed.fedWhenReady[i] - f.soundEnd;
                QVERIFY2(waited >= lookAhead - 1e-9, qPrintable(QString::number(waited)));
                QVERIFY2(waited <= session.latencySeconds() + 0.01 + 1e-9, qPrintable(QString::number(waited)));
            }
        }
        // Most frames come out before the sound ends.
        QVERIFY(std::isfinite(fed.fedWhenReady[size_t(expected - 5)]));
        // The labels are the §0 vote over the recognised phones, the features the model's.
        const std::vector<std::string> voted = voteFrameLabels(session.phones(), FrameClock::uniform(25.0, expected), m_acoustic.featureOptions());
        std::vector<int> labels;
        for (const std::string &l : voted)
            labels.push_back(PhoneSet::index(l));
        QCOMPARE(session.frameLabels(), labels);
        const Eigen::MatrixXd batch = model->generate(labels);
        double worst = 0;
        for (int i = 0; i < expected; ++i) {
            QCOMPARE(fed.frames[size_t(i)].label, labels[size_t(i)]);
            worst = std::max(worst, (fed.frames[size_t(i)].features - batch.row(i).transpose()).cwiseAbs().maxCoeff());
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
        // Speech was recognised: the sentence's phones, not silence throughout.
        int speech = 0;
        for (int l : labels)
            speech += l != PhoneSet::kSilence;
        QVERIFY(speech > 30);
    }

    void rendersEveryFrame()
    {
        const DynamicModel *model = trained("dpds");
        FaceRenderer renderer(m_aam);
        LiveOptions options;
        options.stillBackground = true;
        LiveSession session(m_acoustic, m_bigram, *model, &renderer, options);
        const std::vector<float> second(m_sound.begin(), m_sound.begin() + 16000);
        const Fed fed = feed(session, second, 4000);
        QCOMPARE(int(fed.frames.size()), 25);
        for (const LiveFrame &f : fed.frames) {
            QCOMPARE(f.image.size(), renderer.frameSize());
            QCOMPARE(f.image.type(), CV_8UC3);
        }
        // The lips close on the frames heard as /p b m/ (the /p/ of "please") and only there.
        LiveSession closing(m_acoustic, m_bigram, *model, &renderer, options);
        const Fed closed = feed(closing, m_sound, 4000);
        options.closeBilabials = false;
        LiveSession asGenerated(m_acoustic, m_bigram, *model, &renderer, options);
        const Fed open = feed(asGenerated, m_sound, 4000);
        QCOMPARE(open.frames.size(), closed.frames.size());
        const BilabialClosure closure(m_aam);
        int bilabial = 0;
        for (size_t i = 0; i < closed.frames.size(); ++i) {
            QCOMPARE(closed.frames[i].label, open.frames[i].label);
            if (PhoneSet::isBilabial(closed.frames[i].label)) {
                ++bilabial;
                QVERIFY(closure.opening(closed.frames[i].features) < 1e-9);
            } else {
                QCOMPARE(closed.frames[i].features, open.frames[i].features);
            }
        }
        QVERIFY(bilabial >= 1);
    }

    void refusesAModelForAnotherAam()
    {
        std::vector<LabelledSequence> smaller = m_training;
        for (LabelledSequence &s : smaller)
            s.features = s.features.leftCols(3).eval();
        const auto model = createDynamicModel("hmm");
        Feedback feedback;
        model->train(smaller, feedback);
        FaceRenderer renderer(m_aam);
        QVERIFY_THROWS_EXCEPTION(Error, LiveSession(m_acoustic, m_bigram, *model, &renderer));
    }

private:
    // A model of `kind` trained on the demo project, once for all the test functions (a DPDS takes
    // long under the sanitizers).
    const DynamicModel *trained(const std::string &kind)
    {
        std::unique_ptr<DynamicModel> &model = m_models[kind];
        if (!model) {
            model = createDynamicModel(kind);
            Feedback feedback;
            model->train(m_training, feedback);
        }
        return model.get();
    }
};

QTEST_GUILESS_MAIN(TestLiveSession)
#include "tst_livesession.moc"
