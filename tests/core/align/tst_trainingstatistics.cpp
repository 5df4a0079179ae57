// Aligner training by parts (AlignerTrainer's flatStartStatistics / accumulate / update and the
// TrainingStatistics file), on four GRID demo clips split into parts:
//  - the summed flat-start statistics of the parts make the flat start of all the clips, and the
//    summed Baum-Welch statistics of the parts the same re-estimated model as reestimate() over
//    all of them (up to the order of the sums);
//  - the file round-trips every number exactly, and merging refuses parts of another model or
//    kind; damaged files (truncated, another format, a negative count) are errors naming the file;
//  - the model file keeps every number exactly too (floats to 9 digits).
#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/BaumWelch.h"
#include "align/TrainingStatistics.h"
#include "io/AtomicFile.h"
#include "io/Transcript.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";

double maxRelativeDifference(const AcousticModel &a, const AcousticModel &b)
{
    double worst = 0;
    for (int j = 0; j < a.stateCount(); ++j) {
        const GaussianMixture &x = a.state(j), &y = b.state(j);
        if (x.size() != y.size())
            return INFINITY;
        auto rel = [](const Eigen::MatrixXf &p, const Eigen::MatrixXf &q) {
            return ((p - q).cwiseAbs().array() / (p.cwiseAbs().array() + 1e-6f)).maxCoeff();
        };
        worst = std::max({worst, double(rel(x.means, y.means)), double(rel(x.variances, y.variances)),
                          double(rel(x.weights, y.weights))});
    }
    return worst;
}

} // namespace

class TestTrainingStatistics : public QObject
{
    Q_OBJECT

    TrainerOptions m_options;
    std::vector<TrainingUtterance> m_all;
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        m_options.mixtureSchedule = {1};
        const AcousticModel features = featureModel(m_options);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        for (const char *id : {"bbaf2n", "bgin3a", "bwbg8n", "lrik4p"}) {
            const Transcript t = readTranscript(kDemo + id + ".align");
            PreparedUtterance u = prepareUtterance(id, kDemo + id + ".mpg", t.words, features, lexicon);
            m_all.push_back({id, u.features, u.pronunciations});
        }
    }

    void partsMakeTheModelOfTheWhole()
    {
        // Flat start: two parts of two clips each.
        const std::vector<TrainingUtterance> first(m_all.begin(), m_all.begin() + 2), second(m_all.begin() + 2, m_all.end());
        FlatStartStatistics flat = AlignerTrainer::flatStartStatistics(first, m_options);
        flat.add(AlignerTrainer::flatStartStatistics(second, m_options));
        const AcousticModel whole = AlignerTrainer::flatStart(m_all, m_options);
        AcousticModel model = AlignerTrainer::flatStart(flat, m_options);
        QVERIFY(maxRelativeDifference(model, whole) < 1e-6);

        // Two Baum-Welch passes, the second after a split to two Gaussians: four parts of one clip.
        AcousticModel reference = whole;
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<double> occupancy, referenceOccupancy;
            Accumulators sum(model);
            for (const TrainingUtterance &u : m_all)
                sum.add(AlignerTrainer::accumulate(model, {u}, m_options));
            QCOMPARE(sum.utterances, 4);
            const double ll = AlignerTrainer::update(model, sum, m_options, &occupancy);
            const double referenceLl = AlignerTrainer::reestimate(reference, m_all, m_options, nullptr, &referenceOccupancy);
            QVERIFY(std::abs(ll - referenceLl) < 1e-9 * std::abs(referenceLl));
            QVERIFY2(maxRelativeDifference(model, reference) < 1e-5, qPrintable(QString::number(maxRelativeDifference(model, reference))));
            if (pass == 0) {
                AlignerTrainer::splitMixtures(model, 2, occupancy, 1.0);
                AlignerTrainer::splitMixtures(reference, 2, referenceOccupancy, 1.0);
            }
        }
        QCOMPARE(model.state(AcousticModel::stateIndex(PhoneSet::kSilence, 1)).size(), 2); // split and re-estimated
    }

    void fileRoundTripsAndMergingChecksTheParts()
    {
        const AcousticModel model = AlignerTrainer::flatStart(m_all, m_options);
        TrainingStatistics bw;
        bw.kind = TrainingStatistics::Kind::BaumWelch;
        bw.model = model;
        bw.baumWelch = AlignerTrainer::accumulate(model, m_all, m_options);
        const std::string path = m_dir.filePath("part.stats").toStdString();
        writeTrainingStatistics(path, bw);
        const TrainingStatistics read = readTrainingStatistics(path);
        QVERIFY(read.kind == TrainingStatistics::Kind::BaumWelch);
        QCOMPARE(read.model.text(), model.text());
        QCOMPARE(read.baumWelch->frames, bw.baumWelch->frames);
        QCOMPARE(read.baumWelch->logLikelihood, bw.baumWelch->logLikelihood);
        for (size_t j = 0; j < bw.baumWelch->states.size(); ++j) {
            QCOMPARE(read.baumWelch->states[j].occupancy, bw.baumWelch->states[j].occupancy);
            QVERIFY(read.baumWelch->states[j].sum == bw.baumWelch->states[j].sum);
            QVERIFY(read.baumWelch->states[j].sumSquares == bw.baumWelch->states[j].sumSquares);
        }

        TrainingStatistics flat;
        flat.model = featureModel(m_options);
        flat.flatStart = AlignerTrainer::flatStartStatistics(m_all, m_options);
        const std::string flatPath = m_dir.filePath("flat.stats").toStdString();
        writeTrainingStatistics(flatPath, flat);
        const TrainingStatistics flatRead = readTrainingStatistics(flatPath);
        QVERIFY(flatRead.flatStart.sum[1] == flat.flatStart.sum[1]);
        QCOMPARE(flatRead.flatStart.frames[0], flat.flatStart.frames[0]);

        // Parts of another kind, or collected under another model, are not merged.
        TrainingStatistics copy = read;
        QVERIFY_THROWS_EXCEPTION(Error, copy.add(flatRead));
        AcousticModel other = model;
        other.setSelfLoop(0, 0.5);
        TrainingStatistics otherPart = read;
        otherPart.model = other;
        QVERIFY_THROWS_EXCEPTION(Error, copy.add(otherPart));
        copy.add(read);
        QCOMPARE(copy.baumWelch->frames, 2 * bw.baumWelch->frames);

        // Damaged files name themselves.
        const std::string bytes = readWholeFile(path);
        const std::string bad = m_dir.filePath("bad.stats").toStdString();
        for (const std::string &damaged : {bytes.substr(0, bytes.size() - 9), std::string("LSTATS02") + bytes.substr(8),
                                           bytes + "x", std::string("hello")}) {
            writeFileAtomically(bad, damaged);
            try {
                readTrainingStatistics(bad);
                QFAIL("a damaged file was read");
            } catch (const Error &e) {
                QCOMPARE(e.file(), bad);
            }
        }
    }

    // The fuzzer's seeds (tests/data/fuzz/trainingstats) are valid files of both kinds.
    void fuzzSeedsAreValid()
    {
        const std::string dir = LIPSYNC_TEST_DATA "/fuzz/trainingstats/";
        QVERIFY(readTrainingStatistics(dir + "dim1-flatstart.stats").kind == TrainingStatistics::Kind::FlatStart);
        const TrainingStatistics bw = readTrainingStatistics(dir + "tiny-d2-m2-baumwelch.stats");
        QVERIFY(bw.kind == TrainingStatistics::Kind::BaumWelch);
        QCOMPARE(bw.baumWelch->frames, 200LL);
    }

    void modelFilesKeepEveryNumber()
    {
        AcousticModel model = AlignerTrainer::flatStart(m_all, m_options);
        AlignerTrainer::reestimate(model, m_all, m_options);
        const std::string path = m_dir.filePath("model.aligner").toStdString();
        model.save(path);
        const AcousticModel read = AcousticModel::load(path);
        QCOMPARE(maxRelativeDifference(read, model), 0.0);
        QCOMPARE(read.text(), model.text());
    }
};

QTEST_GUILESS_MAIN(TestTrainingStatistics)
#include "tst_trainingstatistics.moc"
