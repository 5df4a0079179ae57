// CMU Sphinx's phones as the sound comes in (align/SphinxPhoneRecognizer), on demo clips fed in
// 10 ms blocks (skipped where Debian's pocketsphinx-en-us is not installed):
//  - one decision per 10 ms frame of the sound, in order, each within the lag of the newest
//    frame searched, every one a PhoneSet index, speech among them;
//  - restarting the search at a silence every few seconds (what keeps memory bounded) still
//    decides every 10 ms of the sound, and mostly as one search over the whole sound does (the
//    frames of a restarted search are counted from its own start), also cut within speech;
//  - a model folder that is not there is an error naming it.
#include "align/SphinxAligner.h"
#include "align/SphinxPhoneRecognizer.h"
#include "io/AudioDecoder.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

const std::string kMedia = LIPSYNC_SOURCE_DIR "/resources/demo/media/";

// Feeds `samples` in 10 ms blocks; checks that decisions never run ahead of the lag.
std::vector<int> recognise(SphinxPhoneRecognizer &r, const std::vector<float> &samples, bool *onTime)
{
    std::vector<int> out;
    const size_t block = 160;
    const double lag = r.latencySeconds();
    for (size_t at = 0; at < samples.size(); at += block) {
        const size_t n = std::min(block, samples.size() - at);
        r.push(samples.data() + at, n);
        for (int p : r.takeDecided())
            out.push_back(p);
        // A frame is decided once its centre lies `lag` behind the sound fed (and not later than
        // a block after that).
        const double fed = double(at + n) / 16000.0;
        const double decidedUpTo = double(out.size()) * 0.01;
        if (decidedUpTo > fed + 1e-9 || fed - decidedUpTo > lag + 0.03)
            *onTime = false;
    }
    r.finish();
    for (int p : r.takeDecided())
        out.push_back(p);
    return out;
}

} // namespace

class TestSphinxPhoneRecognizer : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        if (!SphinxAligner::available({}))
            QSKIP("CMU Sphinx's US-English models are not installed (Debian package pocketsphinx-en-us)");
    }

    void decidesEveryFrameInTime()
    {
        const std::vector<float> sound = AudioDecoder::decode(kMedia + "bbaf2n.mpg", 16000).samples;
        SphinxPhoneRecognizer r;
        bool onTime = true;
        const std::vector<int> phones = recognise(r, sound, &onTime);
        QVERIFY(onTime);
        const int expected = int(std::floor(double(sound.size()) / 160.0));
        QVERIFY2(std::abs(int(phones.size()) - expected) <= 3,
                 qPrintable(QString("%1 decisions for %2 frames").arg(phones.size()).arg(expected)));
        QCOMPARE(r.decidedFrames(), int(phones.size()));
        int speech = 0;
        for (int p : phones) {
            QVERIFY(p >= 0 && p < PhoneSet::kCount);
            speech += PhoneSet::isSpeech(p);
        }
        // "bin blue at f two now" is about 1.2 s of the 3 s clip.
        QVERIFY2(speech > 60, qPrintable(QString::number(speech)));
    }

    void restartsKeepEveryFrame()
    {
        std::vector<float> sound;
        for (const char *id : {"bbaf2n", "bgin3a", "lrik4p", "pbav2n"}) {
            const std::vector<float> s = AudioDecoder::decode(kMedia + id + ".mpg", 16000).samples;
            sound.insert(sound.end(), s.begin(), s.end());
        }
        SphinxPhoneOptions restarting;
        restarting.restartSeconds = 2.0; // about once per clip, at its trailing silence
        SphinxPhoneRecognizer once, often(restarting);
        bool onTime = true;
        const std::vector<int> a = recognise(once, sound, &onTime), b = recognise(often, sound, &onTime);
        QVERIFY(onTime);
        // Every 10 ms of the sound is decided, restarted or not.
        QCOMPARE(a.size(), b.size());
        QCOMPARE(int(a.size()), int(sound.size() / 160));
        int same = 0;
        for (size_t i = 0; i < a.size(); ++i)
            same += a[i] == b[i];
        qInfo("%d of %zu frames as one search over the whole sound decides them", same, a.size());
        QVERIFY2(same > 0.8 * double(a.size()), qPrintable(QString("%1 of %2").arg(same).arg(a.size())));
        // Speech that never pauses as long as asked is cut anyway (here within words, every
        // 0.9 s): still one decision per 10 ms.
        SphinxPhoneOptions cutting;
        cutting.restartSeconds = 0.3;
        SphinxPhoneRecognizer cut(cutting);
        const std::vector<int> c = recognise(cut, sound, &onTime);
        QVERIFY(onTime);
        QCOMPARE(c.size(), a.size());
    }

    void missingModelsAreAnError()
    {
        SphinxPhoneOptions o;
        o.modelDir = "/nonexistent/en-us";
        try {
            SphinxPhoneRecognizer r(o);
            QFAIL("a missing model folder was accepted");
        } catch (const Error &e) {
            QVERIFY2(std::string(e.what()).find("/nonexistent") != std::string::npos, e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestSphinxPhoneRecognizer)
#include "tst_sphinxphonerecognizer.moc"
