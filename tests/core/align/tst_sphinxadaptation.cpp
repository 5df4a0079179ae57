// SphinxCodebooks and SphinxAdaptation: the speaker adaptation of SphinxAligner (align --model
// sphinx --adapt), on Debian's pocketsphinx-en-us model (installed by scripts/setup; the tests
// skip only when it is absent).
//  - The codebooks read as pocketsphinx reads them: 42 CI-phone codebooks of 3 x 128 Gaussians
//    in 13 dimensions, every senone's mixture weights summing to one (the quantisation unit).
//  - Parameter recovery: frames drawn from the model's own mixtures moved by a known affine map
//    per stream give back that map (and the identity when not moved).
//  - The two file formats from memory: tiny little- and big-endian parameter files and a sendump
//    (the fuzz seeds) give their values; damaged ones are refused, naming the file.
//  - The transform file is pocketsphinx's MLLR format (A row by row, b, variance scales).
//  - Damaged model files are named: truncated weights, a non-parameter file, a missing file,
//    weights for another number of senones.
#include "align/SphinxAdaptation.h"
#include "align/SphinxAligner.h"
#include "align/SphinxCodebooks.h"
#include "align/SphinxModelDefinition.h"
#include "util/Error.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <tuple>

using namespace lipsync;

namespace {

const std::string kModel = SphinxAligner::kDefaultModelDir;

struct Map
{
    std::vector<Eigen::MatrixXd> w; // per stream, n x n+1: (b | A)
};

// Frames of each CI phone's first emitting senone drawn from its own mixtures (each stream its
// own component, as the model's streams are independent) with means moved by `truth`.
// Returns the estimate's error and, for scale, that of not adapting at all (the identity map).
std::pair<double, double> recoveryError(const SphinxCodebooks &codebooks, const SphinxModelDefinition &mdef, const Map &truth)
{
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform;
    SphinxAdaptation adaptation(codebooks);
    std::vector<std::vector<float>> frame(size_t(codebooks.streams()));
    std::vector<const float *> pointers;
    std::vector<std::tuple<int, int, int>> drawn; // codebook, stream, density of each frame's streams
    for (int f = 0; f < codebooks.streams(); ++f) {
        frame[size_t(f)].resize(size_t(codebooks.streamLength(f)));
        pointers.push_back(frame[size_t(f)].data());
    }
    for (int cb = 0; cb < codebooks.codebooks(); ++cb) {
        const int senone = mdef.senones(cb)[1];
        for (int i = 0; i < 300; ++i) {
            for (int f = 0; f < codebooks.streams(); ++f) {
                double u = uniform(random);
                int d = 0;
                for (; d + 1 < codebooks.densities(); ++d) {
                    u -= std::exp(codebooks.logWeight(f, d, senone));
                    if (u <= 0)
                        break;
                }
                drawn.emplace_back(cb, f, d);
                const int n = codebooks.streamLength(f);
                Eigen::VectorXd xi(n + 1);
                xi[0] = 1;
                xi.tail(n) = codebooks.means(cb, f).row(d).transpose().cast<double>();
                const Eigen::VectorXd mean = truth.w[size_t(f)] * xi;
                for (int k = 0; k < n; ++k)
                    frame[size_t(f)][size_t(k)] = float(mean[k] + std::sqrt(double(codebooks.variances(cb, f)(d, k))) * normal(random));
            }
            adaptation.addFrame(pointers.data(), senone, cb);
        }
    }
    // How far the estimated map puts the means of the Gaussians the frames came from from where
    // the true map puts them, in the Gaussians' standard deviations (root mean square over the
    // frames and dimensions; W's entries alone would mislead: the bias is ill-conditioned
    // against A where the means are large).
    auto error = [&](const std::vector<Eigen::MatrixXd> &estimated) {
        double squares = 0;
        int count = 0;
        for (const auto &[cb, f, d] : drawn) {
            const int n = codebooks.streamLength(f);
            Eigen::VectorXd xi(n + 1);
            xi[0] = 1;
            xi.tail(n) = codebooks.means(cb, f).row(d).transpose().cast<double>();
            const Eigen::VectorXd delta = (estimated[size_t(f)] - truth.w[size_t(f)]) * xi;
            squares += (delta.array().square() / codebooks.variances(cb, f).row(d).transpose().cast<double>().array()).sum();
            count += n;
        }
        return std::sqrt(squares / count);
    };
    std::vector<Eigen::MatrixXd> identity;
    for (const Eigen::MatrixXd &w : truth.w) {
        identity.push_back(Eigen::MatrixXd::Zero(w.rows(), w.cols()));
        identity.back().rightCols(w.rows()).setIdentity();
    }
    return {error(adaptation.transforms()), error(identity)};
}

} // namespace

class TestSphinxAdaptation : public QObject
{
    Q_OBJECT

    std::unique_ptr<SphinxCodebooks> m_codebooks;
    std::unique_ptr<SphinxModelDefinition> m_mdef;

private slots:
    void initTestCase()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        m_mdef = std::make_unique<SphinxModelDefinition>(SphinxModelDefinition::read(kModel + "/mdef"));
        m_codebooks = std::make_unique<SphinxCodebooks>(SphinxCodebooks::read(kModel, m_mdef->senoneCount()));
    }

    void codebooksReadAsPocketsphinxReadsThem()
    {
        const SphinxCodebooks &c = *m_codebooks;
        QCOMPARE(c.codebooks(), m_mdef->ciPhoneCount());
        QCOMPARE(c.streams(), 3);
        QCOMPARE(c.densities(), 128);
        for (int f = 0; f < 3; ++f)
            QCOMPARE(c.streamLength(f), 13);
        QCOMPARE(c.senones(), 5126);
        for (int cb = 0; cb < c.codebooks(); ++cb)
            for (int f = 0; f < 3; ++f) {
                QVERIFY(c.variances(cb, f).minCoeff() >= 1e-4f);
                QVERIFY(c.means(cb, f).allFinite());
            }
        // Each senone's weights are a distribution per stream: 8-bit quantised -log weights in
        // units of 1024 steps of the log base (rounding and flooring leave a few per cent).
        for (int senone : {0, 1, 100, 2500, 5125})
            for (int f = 0; f < 3; ++f) {
                double sum = 0;
                for (int d = 0; d < c.densities(); ++d)
                    sum += std::exp(c.logWeight(f, d, senone));
                QVERIFY2(std::abs(sum - 1.0) < 0.1, qPrintable(QStringLiteral("senone %1 stream %2: %3").arg(senone).arg(f).arg(sum)));
            }
    }

    void recoversAKnownTransform()
    {
        Map identity, moved;
        std::mt19937 random(3);
        std::uniform_real_distribution<double> uniform(-1, 1);
        for (int f = 0; f < 3; ++f) {
            Eigen::MatrixXd w = Eigen::MatrixXd::Zero(13, 14);
            w.rightCols(13).setIdentity();
            identity.w.push_back(w);
            // A non-symmetric A near the identity and a shift of up to 2 (the cepstra's units).
            for (int r = 0; r < 13; ++r) {
                w(r, 0) = 2.0 * uniform(random);
                for (int k = 0; k < 13; ++k)
                    w(r, k + 1) = (r == k ? 0.8 : 0.0) + 0.1 * uniform(random);
            }
            moved.w.push_back(w);
        }
        const auto [unmovedError, unmovedScale] = recoveryError(*m_codebooks, *m_mdef, identity);
        const auto [movedError, movedScale] = recoveryError(*m_codebooks, *m_mdef, moved);
        qInfo("RMS error of the means, in standard deviations: %.3f unmoved, %.3f moved (not adapting: %.3f)",
              unmovedError, movedError, movedScale);
        QCOMPARE(unmovedScale, 0.0);
        QVERIFY2(movedScale > 0.3, qPrintable(QString::number(movedScale)));
        QVERIFY2(unmovedError < 0.1, qPrintable(QString::number(unmovedError)));
        // One pass, with the frames' Gaussians weighed under the unmoved model, gets most of the
        // way (0.14 of 0.35 left); the aligner's second pass is its E-step under the moved one.
        QVERIFY2(movedError < 0.5 * movedScale, qPrintable(QString::number(movedError)));
    }

    void parsesTinyFilesOfBothByteOrders()
    {
        for (const char *name : {"tiny-le.means", "tiny-be.means"}) {
            QFile file(QStringLiteral(LIPSYNC_TEST_DATA "/fuzz/sphinxgauden/") + QLatin1String(name));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const std::string bytes = file.readAll().toStdString();
            const SphinxCodebooks::Gaussians g = SphinxCodebooks::parseGaussians(bytes, name);
            QCOMPARE(g.codebooks, 2);
            QCOMPARE(g.streams, 2);
            QCOMPARE(g.densities, 2);
            QCOMPARE(g.lengths, (std::vector<int>{2, 1}));
            QCOMPARE(g.values.size(), size_t(12));
            for (size_t i = 0; i < g.values.size(); ++i)
                QCOMPARE(g.values[i], float(i) * 0.5f - 1.0f);
            // Cut anywhere: a clean error naming the file.
            for (size_t cut : {size_t(2), size_t(30), size_t(40), size_t(60), bytes.size() - 1}) {
                try {
                    SphinxCodebooks::parseGaussians(bytes.substr(0, cut), name);
                    QFAIL("a truncated parameter file was accepted");
                } catch (const Error &e) {
                    QCOMPARE(e.file(), std::string(name));
                }
            }
        }
        QFile file(QStringLiteral(LIPSYNC_TEST_DATA "/fuzz/sphinxsendump/tiny.sendump"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const std::string bytes = file.readAll().toStdString();
        const std::vector<uint8_t> weights = SphinxCodebooks::parseMixtureWeights(bytes, "tiny.sendump", 2, 2, 3);
        QCOMPARE(weights, (std::vector<uint8_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
        QVERIFY_THROWS_EXCEPTION(Error, SphinxCodebooks::parseMixtureWeights(bytes, "tiny.sendump", 3, 2, 3));
        QVERIFY_THROWS_EXCEPTION(Error, SphinxCodebooks::parseMixtureWeights(bytes, "tiny.sendump", 2, 2, 4));
        QVERIFY_THROWS_EXCEPTION(Error, SphinxCodebooks::parseMixtureWeights(bytes.substr(0, bytes.size() - 1), "tiny.sendump", 2, 2, 3));
    }

    void writesPocketsphinxMllrFormat()
    {
        Eigen::MatrixXd w(2, 3);
        w << 0.5, 1.0, 2.0, //
            -0.25, 3.0, 4.0;
        std::istringstream text(SphinxAdaptation::pocketsphinxText({w, w}));
        std::vector<double> numbers;
        for (double x; text >> x;)
            numbers.push_back(x);
        const std::vector<double> stream{2, 1, 2, 3, 4, 0.5, -0.25, 1, 1};
        std::vector<double> expected{1, 2}; // one class, two streams
        for (int f = 0; f < 2; ++f)
            expected.insert(expected.end(), stream.begin(), stream.end());
        QCOMPARE(numbers, expected);
    }

    void damagedModelFilesAreNamed()
    {
        QTemporaryDir dir;
        const std::filesystem::path copy(dir.path().toStdString());
        for (const char *name : {"means", "variances", "sendump"})
            std::filesystem::copy_file(std::filesystem::path(kModel) / name, copy / name);
        auto expectError = [&](const char *file, int senones, const char *what) {
            try {
                SphinxCodebooks::read(copy.string(), senones);
                QFAIL(qPrintable(QStringLiteral("accepted: %1").arg(QString::fromLatin1(what))));
            } catch (const Error &e) {
                QVERIFY2(e.file() == (copy / file).string(), qPrintable(QString::fromStdString(e.file())));
            }
        };
        // Weights for another model (another number of senones).
        expectError("sendump", 5000, "another senone count");
        // Truncated weights.
        std::filesystem::resize_file(copy / "sendump", 100000);
        expectError("sendump", 5126, "truncated sendump");
        // Not a parameter file.
        std::ofstream(copy / "means") << "not a Sphinx parameter file\n";
        expectError("means", 5126, "text means");
        std::filesystem::remove(copy / "means");
        expectError("means", 5126, "missing means");
    }
};

QTEST_GUILESS_MAIN(TestSphinxAdaptation)
#include "tst_sphinxadaptation.moc"
