// MFCC against an independent reference: the HTK Book's formulas (ch. 5.4, HSigP.c's
// PreEmphasise/Ham/FBank/FBank2MFCC/WeightCepstrum) transcribed literally below with 1-based
// arrays, a direct O(N^2) DFT in double precision and no shared code with core/audio/Mfcc.cpp.
// The reference reproduces HTK's channel assignment loop (loChan/loWt) rather than computing
// triangle weights, so the two codes reach the filter bank by different routes.
#include "audio/Mfcc.h"

#include <QTest>

#include <cmath>
#include <random>
#include <vector>

using namespace lipsync;

namespace {

// One frame of HTK MFCC_0 (c1..c12, c0) for 16 kHz samples in 16-bit units.
std::vector<double> htkReferenceFrame(std::vector<double> s /* 1-based, size N+1 */)
{
    const int N = int(s.size()) - 1; // 400
    const double k = 0.97;
    for (int i = N; i >= 2; --i) // PreEmphasise
        s[i] -= s[i - 1] * k;
    s[1] *= 1.0 - k;
    for (int i = 1; i <= N; ++i) // Ham
        s[i] *= 0.54 - 0.46 * std::cos(2 * M_PI * (i - 1) / (N - 1));
    const int fftN = 512;
    const int numChans = 26;
    const double sampleRate = 16000;
    // FBank: |X(k)| for k = 2..fftN/2 (1-based; bin k is frequency (k-1) * sampleRate / fftN).
    std::vector<double> ek(size_t(fftN / 2) + 1);
    for (int kk = 2; kk <= fftN / 2; ++kk) {
        double re = 0, im = 0;
        for (int n = 1; n <= N; ++n) {
            const double angle = -2 * M_PI * double(kk - 1) * (n - 1) / fftN;
            re += s[n] * std::cos(angle);
            im += s[n] * std::sin(angle);
        }
        ek[size_t(kk)] = std::sqrt(re * re + im * im);
    }
    auto Mel = [&](int kk) { return 1127 * std::log(1 + (kk - 1) * sampleRate / fftN / 700.0); };
    const double mlo = 0, mhi = 1127 * std::log(1 + sampleRate / 2 / 700.0);
    const double ms = mhi - mlo;
    std::vector<double> cf(size_t(numChans) + 2);
    for (int chan = 1; chan <= numChans + 1; ++chan)
        cf[size_t(chan)] = (double(chan) / (numChans + 1)) * ms + mlo;
    std::vector<double> fbank(size_t(numChans) + 1, 0.0);
    for (int kk = 2; kk <= fftN / 2; ++kk) {
        const double melk = Mel(kk);
        int chan = 1;
        while (chan <= numChans + 1 && cf[size_t(chan)] < melk)
            ++chan;
        const int loChan = chan - 1;
        const double loWt = loChan > 0 ? (cf[size_t(loChan) + 1] - melk) / (cf[size_t(loChan) + 1] - cf[size_t(loChan)])
                                       : (cf[1] - melk) / (cf[1] - mlo);
        if (loChan > 0)
            fbank[size_t(loChan)] += ek[size_t(kk)] * loWt;
        if (loChan < numChans)
            fbank[size_t(loChan) + 1] += ek[size_t(kk)] * (1 - loWt);
    }
    for (int i = 1; i <= numChans; ++i)
        fbank[size_t(i)] = std::log(std::max(fbank[size_t(i)], 1.0));
    // FBank2MFCC + WeightCepstrum (L = 22), then FBank2C0.
    const double mfnorm = std::sqrt(2.0 / numChans);
    std::vector<double> c;
    for (int j = 1; j <= 12; ++j) {
        double x = 0;
        for (int kk = 1; kk <= numChans; ++kk)
            x += fbank[size_t(kk)] * std::cos(j * M_PI / numChans * (kk - 0.5));
        c.push_back(x * mfnorm * (1 + 22 / 2.0 * std::sin(j * M_PI / 22)));
    }
    double c0 = 0;
    for (int kk = 1; kk <= numChans; ++kk)
        c0 += fbank[size_t(kk)];
    c.push_back(c0 * mfnorm);
    return c;
}

std::vector<float> testSignal(int samples)
{
    // Two tones, a chirp and deterministic noise, peak about 0.6 of full scale.
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.02);
    std::vector<float> s(static_cast<size_t>(samples));
    for (int i = 0; i < samples; ++i) {
        const double t = i / 16000.0;
        s[size_t(i)] = float(0.3 * std::sin(2 * M_PI * 440 * t) + 0.15 * std::sin(2 * M_PI * 2500 * t)
                             + 0.1 * std::sin(2 * M_PI * (200 + 3000 * t) * t) + noise(rng));
    }
    return s;
}

} // namespace

class TestMfcc : public QObject
{
    Q_OBJECT
private slots:
    void geometryIsHtks()
    {
        const Mfcc mfcc;
        QCOMPARE(mfcc.windowSamples(), 400);
        QCOMPARE(mfcc.shiftSamples(), 160);
        QCOMPARE(mfcc.fftSize(), 512);
        QCOMPARE(mfcc.dimension(), 39);
        QCOMPARE(mfcc.frameCount(399), 0);
        QCOMPARE(mfcc.frameCount(400), 1);
        QCOMPARE(mfcc.frameCount(16000), 98); // (16000 - 400) / 160 + 1
        QCOMPARE(mfccFrameCentre(0), 0.0125);
        // Interior FFT bins are shared between two neighbouring filters with weights summing to 1.
        const Eigen::VectorXf columnSums = mfcc.filterBank().colwise().sum();
        for (int k = 10; k < 225; ++k) // below the last centre (bin ~231) the upper channel exists
            QVERIFY2(std::abs(columnSums[k] - 1.0f) < 1e-5f, qPrintable(QString::number(k)));
    }

    void staticsMatchIndependentReference()
    {
        const std::vector<float> signal = testSignal(16000 / 4);
        const Mfcc mfcc;
        const Eigen::MatrixXf statics = mfcc.computeStatic(signal);
        QCOMPARE(statics.rows(), 23);
        for (int frame : {0, 7, 22}) {
            std::vector<double> s(401);
            for (int i = 0; i < 400; ++i)
                s[size_t(i) + 1] = signal[size_t(frame * 160 + i)] * 32768.0;
            const std::vector<double> ref = htkReferenceFrame(s);
            for (int i = 0; i < 13; ++i)
                QVERIFY2(std::abs(statics(frame, i) - ref[size_t(i)]) < 2e-3 * (1 + std::abs(ref[size_t(i)])),
                         qPrintable(QStringLiteral("frame %1 coefficient %2: %3 vs reference %4")
                                        .arg(frame).arg(i).arg(statics(frame, i)).arg(ref[size_t(i)])));
        }
    }

    void silenceGivesZeroCepstra()
    {
        // All filter outputs are below HTK's floor of 1.0, so every log is 0.
        const Eigen::MatrixXf f = Mfcc().compute(std::vector<float>(4000, 0.0f));
        QCOMPARE(f.rows(), 23);
        QVERIFY(f.cwiseAbs().maxCoeff() == 0.0f);
    }

    void deltasFollowHtkRegression()
    {
        // On a linear ramp the regression slope is exact away from the edges; at the edges HTK
        // replicates the first/last frame: d_0 = (1*(x1-x0) + 2*(x2-x0)) / 10 = 0.5 for slope 1.
        Eigen::MatrixXf ramp(6, 1);
        ramp << 0, 1, 2, 3, 4, 5;
        const Eigen::MatrixXf d = Mfcc::regressionDeltas(ramp, 2);
        QCOMPARE(d.cols(), 2);
        QCOMPARE(d(2, 1), 1.0f);
        QCOMPARE(d(3, 1), 1.0f);
        QCOMPARE(d(0, 1), 0.5f);
        QCOMPARE(d(1, 1), 0.8f); // (1*(2-0) + 2*(3-0)) / 10
        QCOMPARE(d(5, 1), 0.5f);
    }

    void fullVectorLayout()
    {
        const std::vector<float> signal = testSignal(8000);
        const Mfcc mfcc;
        const Eigen::MatrixXf all = mfcc.compute(signal);
        const Eigen::MatrixXf statics = mfcc.computeStatic(signal);
        QCOMPARE(all.cols(), 39);
        QVERIFY(all.leftCols(13).isApprox(statics));
        const Eigen::MatrixXf d = Mfcc::regressionDeltas(statics, 2);
        QVERIFY(all.middleCols(13, 13).isApprox(d.rightCols(13)));
        const Eigen::MatrixXf a = Mfcc::regressionDeltas(d.rightCols(13), 2);
        QVERIFY(all.rightCols(13).isApprox(a.rightCols(13)));
    }

    void rejectsBadOptions()
    {
        MfccOptions o;
        o.sampleRate = 100;
        QVERIFY_THROWS_EXCEPTION(std::exception, Mfcc{o});
        o = {};
        o.cepstra = 30;
        QVERIFY_THROWS_EXCEPTION(std::exception, Mfcc{o});
    }
};

QTEST_GUILESS_MAIN(TestMfcc)
#include "tst_mfcc.moc"
