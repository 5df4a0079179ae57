// Mouths learnt on other speakers as a starting point (animation/MouthShapePrior), on the demo:
// learnt from its tracked, aligned frames, each phone's displacement from the mean shape; with no
// prior weight a person's phone means are their own means (what HMM-mean trains); with a heavy
// weight a phone's mean takes the prior's mouth on the person's face (a prior learnt on the same
// person gives back that phone's own mouth shape); HMM-mean and Brand (over phones or phones in
// context, either covariance) start from it: each phone's means move by the prior's shift before the
// variance compensation; the weight chosen by cross-validation on the person's clips is heavy for
// a prior that knows their mouths and light for one that gives the phones wrong mouths, and a weight
// of 0 gives no shift at all; the file round-trips, and a damaged one is named.
#include "aam/AamModel.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "animation/MouthTrack.h"
#include "dynamics/BrandModel.h"
#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/LabelledFolder.h"
#include "dynamics/ModelFile.h"
#include "tasks/Feedback.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";

// Each phone's own mean of `points` (true) or `features` over the tracks; frames counted.
Eigen::VectorXd ownMean(const std::vector<MouthTrack> &tracks, int phone, bool points, int *frames)
{
    Eigen::VectorXd sum;
    *frames = 0;
    for (const MouthTrack &t : tracks)
        for (int f = 0; f < t.frameCount(); ++f)
            if (t.phones[size_t(f)] == phone) {
                const Eigen::VectorXd row = (points ? t.points : t.features).row(f).transpose();
                sum = *frames == 0 ? row : Eigen::VectorXd(sum + row);
                ++*frames;
            }
    return sum / double(std::max(1, *frames));
}

} // namespace

class TestMouthShapePrior : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        m_project = Project::load(kDemo);
        m_aam = std::make_unique<AamModel>(AamModel::load(m_project.resolve(m_project.aam()->file)));
        m_measurer = std::make_unique<MouthMeasurer>(*m_aam);
        m_tracks = projectMouthTracks(*m_measurer, m_project);
        m_prior = MouthShapePrior::learn(m_tracks);
        m_aw = PhoneSet::index("AW"); // "now", in most demo clips
    }

    void learnsEachPhonesDisplacement()
    {
        QCOMPARE(m_prior.meanShape().size(), 46);
        QCOMPARE(m_prior.displacements().rows(), PhoneSet::kCount);
        int frames = 0;
        ownMean(m_tracks, m_aw, true, &frames);
        QVERIFY(frames > 10);
        QCOMPARE(int(m_prior.frames()(m_aw)), frames);
        QVERIFY(m_prior.displacements().row(m_aw).norm() > 0);
        QCOMPARE(m_prior.displacements().row(PhoneSet::index("ZH")).norm(), 0.0); // never said: no displacement
        QVERIFY_THROWS_EXCEPTION(Error, MouthShapePrior::learn({}));
    }

    void withoutWeightAPersonKeepsTheirOwnMeans()
    {
        const Eigen::MatrixXd means = m_prior.personMeans(m_tracks, 0.0);
        int frames = 0;
        const Eigen::VectorXd own = ownMean(m_tracks, m_aw, false, &frames);
        QVERIFY(means.row(m_aw).transpose().isApprox(own, 1e-9));
    }

    void aHeavyWeightGivesThePriorsMouthOnThePersonsFace()
    {
        // The prior learnt on this very person: its mouth for /AW/ is /AW/'s own mean shape.
        const Eigen::MatrixXd means = m_prior.personMeans(m_tracks, 1e9);
        int frames = 0;
        const Eigen::VectorXd ownShape = ownMean(m_tracks, m_aw, true, &frames);
        const Eigen::VectorXd shape = m_measurer->shape(means.row(m_aw).transpose());
        const double error = (shape - ownShape).norm() / (ownShape - m_prior.meanShape()).norm();
        QVERIFY2(error < 0.2, qPrintable(QString::number(error)));
        // And it moves the mouth as the phone does, away from the mean.
        QVERIFY((shape - m_prior.meanShape()).dot(ownShape - m_prior.meanShape()) > 0);
    }

    void theShiftIsWhatThePriorAddsToTheOwnMeans()
    {
        QCOMPARE(m_prior.personShift(m_tracks, 0.0).norm(), 0.0);
        const Eigen::MatrixXd shift = m_prior.personShift(m_tracks, 80.0);
        QVERIFY(shift.isApprox(m_prior.personMeans(m_tracks, 80.0) - m_prior.personMeans(m_tracks, 0.0)));
        const std::vector<LabelledSequence> sequences = loadProjectSequences(m_project);
        QVERIFY(projectPriorShift(m_prior, *m_measurer, m_project, sequences, 80.0).isApprox(shift, 1e-9));
    }

    void hmmMeanAndBrandStartFromTheShift()
    {
        const std::vector<LabelledSequence> sequences = loadProjectSequences(m_project);
        const Eigen::Index d = sequences.front().features.cols();
        const Eigen::MatrixXd shift = 0.1 * Eigen::MatrixXd::Random(PhoneSet::kCount, d);
        auto trained = [&](const std::string &kind, ModelOptions options, bool shifted) {
            if (shifted)
                options.meanShift = shift;
            std::unique_ptr<DynamicModel> model = createDynamicModel(kind, options);
            Feedback quiet;
            model->train(sequences, quiet);
            return model;
        };
        {
            const auto plain = trained("hmm", {}, false), moved = trained("hmm", {}, true);
            QVERIFY(dynamic_cast<HmmMeanModel &>(*moved).means().isApprox(
                dynamic_cast<HmmMeanModel &>(*plain).means() + shift, 1e-12));
        }
        for (const BrandCovariance covariance : {BrandCovariance::Diagonal, BrandCovariance::Full}) {
            ModelOptions options;
            options.brand.covariance = covariance;
            const auto plain = trained("brand", options, false), moved = trained("brand", options, true);
            const auto &a = dynamic_cast<BrandModel &>(*plain), &b = dynamic_cast<BrandModel &>(*moved);
            QVERIFY(b.staticMean.isApprox(a.staticMean + shift, 1e-12));
            QVERIFY(b.deltaMean.isApprox(a.deltaMean, 1e-12));
            if (covariance == BrandCovariance::Full) {
                QVERIFY(b.jointMean.leftCols(d).isApprox(a.jointMean.leftCols(d) + shift, 1e-12));
                QVERIFY(b.jointMean.rightCols(d).isApprox(a.jointMean.rightCols(d), 1e-12));
            }
        }
        {
            // Phones in context: every state by its own phone's row; the compensation is estimated on
            // the moved means, so it differs from the plain model's.
            ModelOptions options;
            options.contextStates = true;
            options.context.minOccupancy = 20;
            options.compensateVariance = true;
            const auto plain = trained("brand", options, false), moved = trained("brand", options, true);
            const auto &a = dynamic_cast<ContextDependentModel &>(*plain), &b = dynamic_cast<ContextDependentModel &>(*moved);
            QVERIFY(a.tree().stateCount() > PhoneSet::kCount); // the demo makes context states
            const auto &innerA = dynamic_cast<const BrandModel &>(a.inner()), &innerB = dynamic_cast<const BrandModel &>(b.inner());
            for (int s = 0; s < a.tree().stateCount(); ++s)
                QVERIFY((innerB.staticMean.row(s) - innerA.staticMean.row(s) - shift.row(a.tree().phoneOf(s))).norm() < 1e-9);
            QVERIFY(!b.compensationMean().isApprox(a.compensationMean()) || !b.compensationGain().isApprox(a.compensationGain()));
        }
        // Kinds without per-phone means: createDynamicModel leaves them alone, a shift set anyway is
        // refused by train(); a shift of the wrong size is refused too.
        ModelOptions briefly; // what is checked is that the shift is left alone, not the fit
        briefly.slds.initIterations = 2;
        briefly.slds.maxIterations = 2;
        QVERIFY(trained("slds", briefly, true)->isTrained());
        std::unique_ptr<DynamicModel> slds = createDynamicModel("slds");
        slds->setMeanShift(shift);
        Feedback quiet;
        QVERIFY_THROWS_EXCEPTION(Error, slds->train(sequences, quiet));
        std::unique_ptr<DynamicModel> brand = createDynamicModel("brand");
        brand->setMeanShift(Eigen::MatrixXd::Zero(PhoneSet::kCount, d + 1));
        QVERIFY_THROWS_EXCEPTION(Error, brand->train(sequences, quiet));
    }

    void crossValidationWeighsAPriorByWhatItPredicts()
    {
        // A prior that knows this person's mouths (learnt on all their clips, the held-out ones
        // too) predicts held-out frames better than the other clips' own means: it gets weight.
        const MouthShapePrior::WeightChoice right = m_prior.chooseWeight(m_tracks);
        QCOMPARE(right.folds, 5);
        QCOMPARE(right.errors.size(), MouthShapePrior::weightCandidates().size());
        QVERIFY2(right.kappa >= 80, qPrintable(QString::number(right.kappa)));
        QVERIFY(right.errors.back() < 0.9 * right.errors.front());
        // Every speech phone's mouth given to another phone: wrong mouths, so little of it is taken
        // (a light weight of any mouth still steadies a phone seen in a few frames), and taken
        // heavily they predict worse than the person's own means.
        std::vector<MouthTrack> relabelled = m_tracks;
        for (MouthTrack &t : relabelled)
            for (int &p : t.phones)
                if (PhoneSet::isSpeech(p))
                    p = (p + 7) % PhoneSet::kSilence;
        const MouthShapePrior wrong = MouthShapePrior::learn(relabelled);
        const MouthShapePrior::WeightChoice refused = wrong.chooseWeight(m_tracks);
        QVERIFY2(refused.kappa <= 5, qPrintable(QString::number(refused.kappa)));
        QVERIFY(refused.errors.back() > 1.1 * refused.errors.front());
        // personShift(kCrossValidated) is the shift at the chosen weight.
        QVERIFY(m_prior.personShift(m_tracks, MouthShapePrior::kCrossValidated)
                    .isApprox(m_prior.personShift(m_tracks, right.kappa), 1e-12));
        QVERIFY(wrong.personShift(m_tracks, MouthShapePrior::kCrossValidated)
                    .isApprox(wrong.personShift(m_tracks, refused.kappa), 1e-12));
        double used = -2;
        const std::vector<LabelledSequence> sequences = loadProjectSequences(m_project);
        projectPriorShift(m_prior, *m_measurer, m_project, sequences, MouthShapePrior::kCrossValidated, &used);
        QCOMPARE(used, right.kappa);
        // Weighed at nothing: no shift at all, so the model says it started from its own frames.
        QCOMPARE(projectPriorShift(m_prior, *m_measurer, m_project, sequences, 0.0, &used).size(), Eigen::Index(0));
        QCOMPARE(used, 0.0);
        // One clip cannot be split: the default weight, and no folds.
        const MouthShapePrior::WeightChoice single = m_prior.chooseWeight({m_tracks.front()});
        QCOMPARE(single.folds, 0);
        QCOMPARE(single.kappa, MouthShapePrior::kDefaultKappa);
    }

    void roundTripsAndNamesADamagedFile()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("demo.mouthprior").toStdString();
        m_prior.save(path);
        const MouthShapePrior back = MouthShapePrior::load(path);
        QVERIFY(back.meanShape().isApprox(m_prior.meanShape(), 1e-12));
        QVERIFY(back.displacements().isApprox(m_prior.displacements(), 1e-12));
        QCOMPARE(back.frames(), m_prior.frames());
        const std::string broken = dir.filePath("broken.mouthprior").toStdString();
        writeFileAtomically(broken, "{\"format\": \"lipsync-mouth-prior\", \"version\": 1, \"meanShape\": [1, 2]}");
        try {
            MouthShapePrior::load(broken);
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY2(QString::fromStdString(e.what()).contains(QStringLiteral("broken.mouthprior")), e.what());
            QVERIFY2(QString::fromStdString(e.what()).contains(QStringLiteral("meanShape")), e.what());
        }
    }

private:
    Project m_project;
    std::unique_ptr<AamModel> m_aam;
    std::unique_ptr<MouthMeasurer> m_measurer;
    std::vector<MouthTrack> m_tracks;
    MouthShapePrior m_prior;
    int m_aw = -1;
};

QTEST_MAIN(TestMouthShapePrior)
#include "tst_mouthshapeprior.moc"
