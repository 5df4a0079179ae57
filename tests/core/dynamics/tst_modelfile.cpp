// Model files (versioned JSON) for all four kinds, and bad input of the common interface.
#include "SyntheticDynamics.h"

#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/ModelFile.h"
#include "io/AtomicFile.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <tuple>

using namespace lipsync;
using namespace lipsync::test;

namespace {

std::vector<LabelledSequence> data(unsigned seed = 1, int d = 3)
{
    std::mt19937 rng(seed);
    const DpdsTruth truth = randomDpdsTruth(rng, d, 0.1);
    return dpdsDataset(rng, truth, {0, 2, 6, 9, 21}, 12, 30);
}

} // namespace

class TestModelFile : public QObject
{
    Q_OBJECT

    // An HMM-mean model trained on the synthetic sequences.
    static HmmMeanModel trainedHmm()
    {
        HmmMeanModel model;
        Feedback feedback;
        model.train(data(), feedback);
        return model;
    }

private slots:
    // The ids are the model files' and the CLI's vocabulary: fixed, each parsed back to its kind,
    // and the factory builds a model that reports it.
    void kindIds()
    {
        QCOMPARE(dynamicModelKinds(), (std::vector<std::string>{"hmm", "brand", "slds", "dpds"}));
        QCOMPARE(allModelKinds().size(), dynamicModelKinds().size());
        for (ModelKind kind : allModelKinds()) {
            QCOMPARE(parseModelKind(modelKindId(kind)), std::optional<ModelKind>(kind));
            QCOMPARE(createDynamicModel(kind)->kind(), std::string(modelKindId(kind)));
        }
        QVERIFY(!parseModelKind("DPDS"));
        QVERIFY(!isDynamicModelKind("aam"));
        QCOMPARE(modelKindIdList(), std::string("dpds, slds, brand or hmm"));
        QCOMPARE(modelKindIdList("|", "|"), std::string("dpds|slds|brand|hmm"));
    }

    void roundTrip_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<bool>("full");
        QTest::addColumn<bool>("compensated");
        QTest::addColumn<bool>("context");
        for (const std::string &kind : dynamicModelKinds()) {
            QTest::newRow(kind.c_str()) << QString::fromStdString(kind) << false << false << false;
            QTest::newRow((kind + " compensated").c_str()) << QString::fromStdString(kind) << false << true << false;
            QTest::newRow((kind + " in context").c_str()) << QString::fromStdString(kind) << false << true << true;
        }
        QTest::newRow("brand full") << QStringLiteral("brand") << true << false << false;
        QTest::newRow("slds full") << QStringLiteral("slds") << true << false << false;
    }
    void roundTrip()
    {
        QFETCH(QString, kind);
        QFETCH(bool, full);
        QFETCH(bool, compensated);
        QFETCH(bool, context);
        ModelOptions options;
        options.compensateVariance = compensated;
        options.contextStates = context;
        options.context.minOccupancy = 10;
        options.brand.covariance = full ? BrandCovariance::Full : BrandCovariance::Diagonal;
        options.slds.fullA = full;
        options.slds.fullNoise = full;
        options.slds.maxIterations = 5;
        auto model = createDynamicModel(kind.toStdString(), options);
        Feedback feedback;
        const auto training = data();
        model->train(training, feedback);
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("model.json")).toStdString();
        saveModel(*model, path, "aam-1234");
        std::string aam;
        auto loaded = loadModel(path, "aam-1234", &aam);
        QCOMPARE(aam, std::string("aam-1234"));
        QCOMPARE(loaded->kind(), model->kind());
        QCOMPARE(loaded->dimension(), 3);
        QCOMPARE(loaded->compensatesVariance(), compensated);
        QCOMPARE(loaded->compensationGain(), model->compensationGain());
        QCOMPARE(loaded->compensationDetailGain(), model->compensationDetailGain());
        QCOMPARE(loaded->compensationWindow(), model->compensationWindow());
        if (context) {
            const auto *trained = dynamic_cast<const ContextDependentModel *>(model.get());
            const auto *read = dynamic_cast<const ContextDependentModel *>(loaded.get());
            QVERIFY(trained && read);
            QVERIFY2(trained->tree().stateCount() > PhoneSet::kCount, "the data's contexts split some phone");
            QCOMPARE(read->tree().stateCount(), trained->tree().stateCount());
            QCOMPARE(read->inner().stateCount(), trained->tree().stateCount());
        }
        std::mt19937 rng(5);
        const std::vector<int> labels = randomLabels(rng, 40, {0, 2, 6, 11});
        QVERIFY(loaded->generate(labels) == model->generate(labels)); // exact round trip
        const auto &s = training.front();
        QCOMPARE(loaded->logLikelihood(s.labels, s.features), model->logLikelihood(s.labels, s.features));
        // Saving again gives the same file.
        const std::string again = dir.filePath(QStringLiteral("again.json")).toStdString();
        saveModel(*loaded, again, aam);
        QCOMPARE(readWholeFile(again), readWholeFile(path));
    }

    // A model started from other speakers records the shift of its means: read back as it was
    // written, not applied again, and carried into a retraining; a shift of the wrong size or not
    // a matrix is named.
    void priorShiftIsRecorded()
    {
        const auto training = data();
        Feedback feedback;
        for (const char *kind : {"hmm", "brand"}) {
            ModelOptions options;
            options.meanShift = Eigen::MatrixXd::Constant(PhoneSet::kCount, 3, 0.25);
            options.meanShift(0, 1) = -0.5;
            options.priorWeight = 20;
            auto model = createDynamicModel(kind, options);
            model->train(training, feedback);
            QTemporaryDir dir;
            const std::string path = dir.filePath(QStringLiteral("m.json")).toStdString();
            saveModel(*model, path, "aam");
            auto loaded = loadModel(path);
            QCOMPARE(loaded->meanShift(), options.meanShift);
            std::mt19937 rng(3);
            const std::vector<int> labels = randomLabels(rng, 30, {0, 2, 6});
            QVERIFY(loaded->generate(labels) == model->generate(labels)); // not shifted twice
            QCOMPARE(retrainingOptions(*loaded).meanShift, options.meanShift);
            QCOMPARE(loaded->priorWeight(), 20.0); // how much the prior weighed, recorded
            QCOMPARE(retrainingOptions(*loaded).priorWeight, 20.0);
            // Without one, none is written.
            auto own = createDynamicModel(kind);
            own->train(training, feedback);
            saveModel(*own, path, "aam");
            QVERIFY(readWholeFile(path).find("\"prior\"") == std::string::npos);
            QCOMPARE(loadModel(path)->meanShift().size(), Eigen::Index(0));
            // A shift of another size.
            saveModel(*model, path, "aam");
            QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(readWholeFile(path))).object();
            o[QStringLiteral("prior")] = QJsonObject{{QStringLiteral("meanShift"), QJsonArray{QJsonArray{1, 2, 3}}}};
            writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
            const std::string e = errorOf([&] { loadModel(path); });
            QVERIFY2(e.find("prior") != std::string::npos && e.find(path) != std::string::npos, e.c_str());
            // A weight that is no number of frames; none at all reads as not recorded.
            saveModel(*model, path, "aam");
            o = QJsonDocument::fromJson(QByteArray::fromStdString(readWholeFile(path))).object();
            QJsonObject prior = o.value(QStringLiteral("prior")).toObject();
            prior[QStringLiteral("weight")] = -3;
            o[QStringLiteral("prior")] = prior;
            writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
            const std::string w = errorOf([&] { loadModel(path); });
            QVERIFY2(w.find("weight") != std::string::npos && w.find(path) != std::string::npos, w.c_str());
            prior.remove(QStringLiteral("weight"));
            o[QStringLiteral("prior")] = prior;
            writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
            QCOMPARE(loadModel(path)->priorWeight(), 0.0);
            QCOMPARE(loadModel(path)->meanShift(), options.meanShift);
        }
    }

    // The model records the frame rate of its training sequences and keeps it through its file;
    // sequences at two rates are refused (rates 1 % apart or less are one, recorded as their mean
    // over the frames), a rate in the file that is not one too.
    void frameRate()
    {
        std::vector<LabelledSequence> training = data();
        for (LabelledSequence &s : training)
            s.frameRate = 29.97;
        HmmMeanModel model;
        Feedback feedback;
        model.train(training, feedback);
        QCOMPARE(model.frameRate(), 29.97);
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("m.json")).toStdString();
        saveModel(model, path, "aam");
        QCOMPARE(loadModel(path)->frameRate(), 29.97);
        std::string text = readWholeFile(path);
        text.replace(text.find("\"frameRate\":29.97"), 17, "\"frameRate\":-25");
        writeFileAtomically(path, text);
        const std::string e = errorOf([&] { loadModel(path); });
        QVERIFY2(e.find("frameRate") != std::string::npos && e.find(path) != std::string::npos, e.c_str());

        // NTSC's exact rate beside the container's rounded one, and 30: one rate.
        const double ntsc = 30000.0 / 1001.0;
        training.back().frameRate = ntsc;
        HmmMeanModel nearly;
        nearly.train(training, feedback);
        double frames = 0, expected = 0;
        for (const LabelledSequence &s : training) {
            frames += double(s.features.rows());
            expected += double(s.features.rows()) * s.frameRate;
        }
        QVERIFY(nearly.frameRate() > 29.97 && nearly.frameRate() < ntsc);
        QVERIFY(std::abs(nearly.frameRate() - expected / frames) < 1e-12);
        training.back().frameRate = 30.0;
        HmmMeanModel().train(training, feedback);
        training.back().frameRate = 25.0;
        const std::string mixed = errorOf([&] { HmmMeanModel().train(training, feedback); });
        QVERIFY2(mixed.find("29.97 and 25 frames/s") != std::string::npos, mixed.c_str());
        // Sequences that say nothing of their rate (synthetic ones) leave it unknown, and unsaved.
        HmmMeanModel unknown;
        unknown.train(data(), feedback);
        QCOMPARE(unknown.frameRate(), 0.0);
        saveModel(unknown, path, "aam");
        QVERIFY(readWholeFile(path).find("frameRate") == std::string::npos);
    }

    // The aligner a model's phones came from is read back as written (its model and adapt only),
    // absent when not recorded, and a malformed record is named.
    void trainingAlignerIsRecorded()
    {
        HmmMeanModel model = trainedHmm();
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("m.json")).toStdString();
        saveModel(model, path, "aam");
        QVERIFY(!modelTrainingAligner(path));
        QVERIFY(readWholeFile(path).find("aligner") == std::string::npos);

        AlignerChoice generic{"sphinx", true};
        generic.transcriptFit = true; // how one alignment measured, not whose aligner: not kept
        model.setTrainingAligner(generic);
        QVERIFY(!model.trainingAligner()->transcriptFit);
        saveModel(model, path, "aam");
        const std::optional<AlignerChoice> read = modelTrainingAligner(path);
        QVERIFY(read && read->model == "sphinx" && read->adapt);
        for (const std::string own : {std::string("/projects/me/aligner/me.aligner"), std::string()}) {
            model.setTrainingAligner(AlignerChoice{own, false});
            saveModel(model, path, "aam");
            const std::optional<AlignerChoice> back = loadModel(path)->trainingAligner();
            QVERIFY(back && back->model == own && !back->adapt);
        }

        const std::string text = readWholeFile(path);
        for (const std::string bad : {std::string("\"aligner\":\"sphinx\""),
                                      std::string("\"aligner\":{\"adapt\":true}"),
                                      std::string("\"aligner\":{\"model\":\"sphinx\",\"adapt\":1}")}) {
            std::string t = text;
            const size_t from = t.find("\"aligner\":");
            const size_t to = t.find('}', from) + 1;
            t.replace(from, to - from, bad);
            writeFileAtomically(path, t);
            const std::string e = errorOf([&] { loadModel(path); });
            QVERIFY2(e.find("aligner") != std::string::npos && e.find(path) != std::string::npos, e.c_str());
        }
    }

    void rejectsOtherVersionAamAndLabels()
    {
        HmmMeanModel model = trainedHmm();
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("m.json")).toStdString();
        saveModel(model, path, "aam-A");
        std::string e = errorOf([&] { loadModel(path, "aam-B"); });
        QVERIFY2(e.find("aam-A") != std::string::npos && e.find("aam-B") != std::string::npos, e.c_str());
        QVERIFY(e.find(path) != std::string::npos);
        // The one AAM rule (modelFitsAam): its own identifier, the project's name for it, or a
        // model that names no AAM (trained from bare feature files) fits; another AAM does not.
        QVERIFY(modelFitsAam("aam-A", "aam-A"));
        QVERIFY(modelFitsAam("GRID s1 (demo)", "aam-A", "GRID s1 (demo)"));
        QVERIFY(modelFitsAam(kUnspecifiedAam, "aam-A") && modelFitsAam("", "aam-A"));
        QVERIFY(!modelFitsAam("aam-B", "aam-A") && !modelFitsAam("aam-B", "aam-A", "GRID s1 (demo)"));
        const std::string bare = dir.filePath(QStringLiteral("bare.json")).toStdString();
        saveModel(model, bare, kUnspecifiedAam);
        QVERIFY(loadModel(bare, "aam-B")); // as render and Live take it
        const std::string text = readWholeFile(path);
        auto rewrite = [&](const std::string &from, const std::string &to) {
            std::string t = text;
            const size_t at = t.find(from);
            QVERIFY(at != std::string::npos);
            t.replace(at, from.size(), to);
            writeFileAtomically(path, t);
        };
        rewrite("\"version\":1", "\"version\":2");
        e = errorOf([&] { loadModel(path); });
        QVERIFY2(e.find("version 2 is not supported") != std::string::npos, e.c_str());
        rewrite("\"AA\"", "\"AX\"");
        QVERIFY(errorOf([&] { loadModel(path); }).find("label set") != std::string::npos);
        rewrite("\"kind\":\"hmm\"", "\"kind\":\"lstm\"");
        QVERIFY(errorOf([&] { loadModel(path); }).find("unknown model kind") != std::string::npos);
        rewrite("\"variance\":", "\"varianc\":");
        QVERIFY(errorOf([&] { loadModel(path); }).find("variance") != std::string::npos);
        writeFileAtomically(path, "{ not json");
        QVERIFY(errorOf([&] { loadModel(path); }).find("not a model file") != std::string::npos);
        QVERIFY(!errorOf([&] { loadModel(path + ".missing"); }).empty());
        QVERIFY(!errorOf([&] { createDynamicModel("lstm"); }).empty());
        QVERIFY(!errorOf([&] { saveModel(HmmMeanModel(), path, "x"); }).empty());
    }

    void badTrainingInput()
    {
        for (const std::string &kind : dynamicModelKinds()) {
            auto model = createDynamicModel(kind);
            Feedback feedback;
            auto training = data();
            training[3].features(5, 1) = std::numeric_limits<double>::quiet_NaN();
            std::string e = errorOf([&] { model->train(training, feedback); });
            QVERIFY2(e.find("seq3") != std::string::npos && e.find("not finite") != std::string::npos, e.c_str());
            training = data();
            training[2].features(0, 0) = std::numeric_limits<double>::infinity();
            QVERIFY(errorOf([&] { model->train(training, feedback); }).find("seq2") != std::string::npos);
            training = data();
            training[1].labels.pop_back();
            e = errorOf([&] { model->train(training, feedback); });
            QVERIFY2(e.find("seq1") != std::string::npos && e.find("feature rows") != std::string::npos, e.c_str());
            training = data();
            training[4].labels[2] = 41;
            QVERIFY(errorOf([&] { model->train(training, feedback); }).find("outside") != std::string::npos);
            QVERIFY(!errorOf([&] { model->train({}, feedback); }).empty());
            QVERIFY(!model->isTrained());
            // Untrained models refuse to generate.
            QVERIFY(!errorOf([&] { model->generate({1, 2}); }).empty());
            // One-frame sequences are valid training data and generation input.
            training = data();
            training.push_back(LabelledSequence{"single", {6}, Eigen::MatrixXd::Constant(1, 3, 0.5)});
            model->train(training, feedback);
            QCOMPARE(model->generate({6}).rows(), Eigen::Index(1));
            QVERIFY(!errorOf([&] { model->generate({}); }).empty());
            QVERIFY(!errorOf([&] { model->generate({3, -1}); }).empty());
            QVERIFY(!errorOf([&] { model->logLikelihood({3, 3}, Eigen::MatrixXd::Zero(3, 3)); }).empty());
            // GRID lacks 7 phonemes: generating them backs off, never crashes.
            const std::vector<int> unseen{PhoneSet::index("ER"), PhoneSet::index("HH"), PhoneSet::index("NG"),
                                          PhoneSet::index("OY"), PhoneSet::index("SH"), PhoneSet::index("UH"),
                                          PhoneSet::index("ZH")};
            const Eigen::MatrixXd Y = model->generate(unseen);
            QVERIFY(Y.allFinite());
            QVERIFY(std::isfinite(model->logLikelihood(unseen, Y)));
        }
    }

    // Variance compensation (docs/models.md §5.1), trained on the training part alone: the slow
    // part s (7-frame centred mean, edges clamped) and the detail f - s (f the 3-frame centred
    // mean) of the trajectories generated for the training labels are scaled by the ratio of the
    // training features' spread in that band to theirs (unless a gain reached its bound), and the
    // generated trajectory is m + g (s - m) + h (f - s) + (y - f); without it the model generates
    // its own most likely trajectory unchanged.
    void varianceCompensationMatchesTheTrainingSpread()
    {
        // The moving means as the documentation states them, written out separately from the model's.
        auto centredMean = [](const Eigen::MatrixXd &y, int half) {
            Eigen::MatrixXd s = Eigen::MatrixXd::Zero(y.rows(), y.cols());
            for (Eigen::Index t = 0; t < y.rows(); ++t)
                for (Eigen::Index k = t - half; k <= t + half; ++k)
                    s.row(t) += y.row(std::min(std::max<Eigen::Index>(k, 0), y.rows() - 1)) / double(2 * half + 1);
            return s;
        };
        auto slow = [&](const Eigen::MatrixXd &y) { return centredMean(y, 3); };
        auto fast = [&](const Eigen::MatrixXd &y) { return centredMean(y, 1); };
        auto bounded = [](double gain) {
            return std::clamp(gain, DynamicModel::kMinCompensationGain, DynamicModel::kMaxCompensationGain);
        };
        QCOMPARE(DynamicModel::kCompensationWindow, 7);
        QCOMPARE(DynamicModel::kCompensationFastWindow, 3);
        for (const std::string &kind : dynamicModelKinds()) {
            ModelOptions options;
            options.slds.maxIterations = 5;
            auto plain = createDynamicModel(kind, options);
            options.compensateVariance = true;
            auto compensated = createDynamicModel(kind, options);
            Feedback feedback;
            const auto training = data(4);
            plain->train(training, feedback);
            compensated->train(training, feedback);
            QVERIFY(!plain->compensatesVariance());
            QVERIFY(compensated->compensatesVariance());
            QCOMPARE(compensated->compensationWindow(), 7);
            QCOMPARE(compensated->compensationFastWindow(), 3);
            const std::vector<int> &labels = training.front().labels;
            QVERIFY(plain->generate(labels) == plain->generateMostLikely(labels));
            QVERIFY(compensated->generateMostLikely(labels) == plain->generateMostLikely(labels));

            const Eigen::VectorXd &m = compensated->compensationMean();
            const Eigen::MatrixXd &g = compensated->compensationGain(), &h = compensated->compensationDetailGain();
            Eigen::MatrixXd realSlow = Eigen::MatrixXd::Zero(3, 3), rawSlow = realSlow, realDetail = realSlow,
                            rawDetail = realSlow;
            for (const LabelledSequence &s : training) {
                const Eigen::MatrixXd raw = plain->generate(s.labels);
                const Eigen::MatrixXd sr = slow(s.features), sg = slow(raw), fr = fast(s.features), fg = fast(raw);
                const Eigen::MatrixXd a = sr.rowwise() - m.transpose(), b = sg.rowwise() - m.transpose();
                realSlow += a.transpose() * a;
                rawSlow += b.transpose() * b;
                realDetail += (fr - sr).transpose() * (fr - sr);
                rawDetail += (fg - sg).transpose() * (fg - sg);
                // y' = m + G (s - m) + H (f - s) + (y - f), frame by frame (G, H symmetric).
                const Eigen::MatrixXd expected = ((b * g + (fg - sg) * h + (raw - fg)).rowwise() + m.transpose());
                QVERIFY2((compensated->generate(s.labels) - expected).cwiseAbs().maxCoeff() < 1e-9, kind.c_str());
            }
            // G and H are the optimal-transport maps of the bands' scatter: symmetric, eigenvalues
            // within the bounds, and where none is at a bound they carry the generated scatter to
            // the recorded one (G S_generated G = S_real).
            for (const auto &[gain, real, raw] : {std::tuple{&g, &realSlow, &rawSlow}, std::tuple{&h, &realDetail, &rawDetail}}) {
                QVERIFY2(((*gain) - gain->transpose()).cwiseAbs().maxCoeff() < 1e-12, kind.c_str());
                const Eigen::VectorXd l = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(*gain).eigenvalues();
                QVERIFY2(l.minCoeff() >= DynamicModel::kMinCompensationGain - 1e-12
                             && l.maxCoeff() <= DynamicModel::kMaxCompensationGain + 1e-12,
                         kind.c_str());
                if (l.minCoeff() > DynamicModel::kMinCompensationGain + 1e-9
                    && l.maxCoeff() < DynamicModel::kMaxCompensationGain - 1e-9) {
                    const double error = ((*gain) * (*raw) * (*gain) - *real).norm() / real->norm();
                    QVERIFY2(error < 1e-5, qPrintable(QStringLiteral("%1: %2").arg(kind.c_str()).arg(error)));
                }
            }
        }
        // A damaged compensation in a model file is refused, naming the field.
        auto model = createDynamicModel("hmm", ModelOptions{{}, {}, {}, true});
        Feedback feedback;
        model->train(data(), feedback);
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("gv.json")).toStdString();
        saveModel(*model, path, "aam");
        const std::string saved = readWholeFile(path);
        for (const auto &[field, damage] : std::vector<std::pair<std::string, std::string>>{
                 {"\"gain\":[[", "-"}, {"\"detailGain\":[[", "-"}, {"\"window\":", "-"}, {"\"fastWindow\":", "-"},
                 {"\"fastWindow\":", "1"}}) { // negative; 13, not below the window
            std::string text = saved;
            const size_t at = text.find(field);
            QVERIFY2(at != std::string::npos, field.c_str());
            text.insert(at + field.size(), damage); // a negative gain or window
            writeFileAtomically(path, text);
            const std::string e = errorOf([&] { loadModel(path); });
            QVERIFY2(e.find("compensation") != std::string::npos && e.find(path) != std::string::npos, e.c_str());
        }
        const std::vector<int> labels = data().front().labels;
        // A file with two bands (no fast window) scales all of the detail y - s by h.
        QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(saved)).object();
        QJsonObject c = o.value("compensation").toObject();
        c.remove("fastWindow");
        o["compensation"] = c;
        writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
        const auto twoBands = loadModel(path);
        QCOMPARE(twoBands->compensationFastWindow(), 0);
        {
            const Eigen::MatrixXd y = twoBands->generateMostLikely(labels), s = slow(y);
            const Eigen::VectorXd &m = twoBands->compensationMean();
            const Eigen::MatrixXd &g = twoBands->compensationGain(), &h = twoBands->compensationDetailGain();
            const Eigen::MatrixXd expected = ((s.rowwise() - m.transpose()) * g + (y - s) * h).rowwise() + m.transpose();
            QVERIFY((twoBands->generate(labels) - expected).cwiseAbs().maxCoeff() < 1e-12);
            QVERIFY((twoBands->generate(labels) - model->generate(labels)).cwiseAbs().maxCoeff() > 1e-6);
        }
        // A file with the whole-trajectory compensation alone (mean and gain) scales by the gain.
        c.remove("window");
        c.remove("detailGain");
        o["compensation"] = c;
        writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
        const auto single = loadModel(path);
        QCOMPARE(single->compensationWindow(), 0);
        const Eigen::MatrixXd y = single->generateMostLikely(labels);
        const Eigen::MatrixXd expected = ((y.rowwise() - single->compensationMean().transpose()) * single->compensationGain()).rowwise()
                                         + single->compensationMean().transpose();
        QVERIFY((single->generate(labels) - expected).cwiseAbs().maxCoeff() < 1e-12);
        // Files with a gain per dimension (each dimension scaled on its own) read them as the
        // diagonal matrix: y' = m + g .* (y - m).
        QJsonArray diagonal;
        for (int k = 0; k < 3; ++k)
            diagonal.append(0.8 + 0.3 * k);
        c["gain"] = diagonal;
        o["compensation"] = c;
        writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
        const auto perDimension = loadModel(path);
        QVERIFY(perDimension->compensationGain().isApprox(Eigen::Vector3d(0.8, 1.1, 1.4).asDiagonal().toDenseMatrix()));
        const Eigen::MatrixXd scaled = ((y.rowwise() - perDimension->compensationMean().transpose()).array().rowwise()
                                        * Eigen::RowVector3d(0.8, 1.1, 1.4).array())
                                           .matrix()
                                           .rowwise()
                                       + perDimension->compensationMean().transpose();
        QVERIFY((perDimension->generate(labels) - scaled).cwiseAbs().maxCoeff() < 1e-12);
        // A gain that is not symmetric is refused.
        QJsonArray skew{QJsonArray{1.0, 0.5, 0.0}, QJsonArray{0.0, 1.0, 0.0}, QJsonArray{0.0, 0.0, 1.0}};
        c["gain"] = skew;
        o["compensation"] = c;
        writeFileAtomically(path, QJsonDocument(o).toJson().toStdString());
        const std::string skewError = errorOf([&] { loadModel(path); });
        QVERIFY2(skewError.find("compensation") != std::string::npos && skewError.find("symmetric") != std::string::npos,
                 skewError.c_str());
    }

    void streamingEqualsBatchForAllKinds()
    {
        for (const std::string &kind : dynamicModelKinds())
            for (bool context : {false, true}) {
                ModelOptions options;
                options.compensateVariance = kind == "dpds" || kind == "brand"; // both ways covered
                options.contextStates = context;
                options.context.minOccupancy = 10;
                auto model = createDynamicModel(kind, options);
                Feedback feedback;
                model->train(data(2), feedback);
                std::mt19937 rng(3);
                const std::vector<int> labels = randomLabels(rng, 300, {0, 2, 6, 9, 21});
                const Eigen::MatrixXd batch = model->generate(labels);
                auto stream = model->streamer();
                Eigen::MatrixXd streamed(batch.rows(), batch.cols());
                Eigen::VectorXd frame(batch.cols());
                Eigen::Index next = 0;
                // Without contexts, frame t is out once label t + latency is in (the compensation
                // holds 3 frames back, Brand's lag more).
                const int latency = stream->latency();
                QCOMPARE(latency < 0, context);
                if (!context && options.compensateVariance)
                    QVERIFY(latency >= DynamicModel::kCompensationWindow / 2);
                for (int pushed = 1; pushed <= int(labels.size()); ++pushed) {
                    stream->push(labels[size_t(pushed) - 1]);
                    while (stream->pop(frame))
                        streamed.row(next++) = frame.transpose();
                    if (!context)
                        QCOMPARE(next, Eigen::Index(std::max(0, pushed - latency)));
                }
                stream->finish();
                while (stream->pop(frame))
                    streamed.row(next++) = frame.transpose();
                QCOMPARE(next, batch.rows());
                QVERIFY(model->generateStreamed(labels) == streamed); // the same, in one call
                // Exact for the recursive models; Brand's fixed-lag frames stay within a few
                // percent of the trajectory's own spread (its lag is chosen for that, §5).
                if (kind == "brand") {
                    const double spread = (batch.rowwise() - batch.colwise().mean()).cwiseAbs().mean();
                    QVERIFY2((streamed - batch).cwiseAbs().mean() <= 0.03 * spread, kind.c_str());
                } else {
                    QVERIFY2((streamed - batch).cwiseAbs().maxCoeff() == 0.0, kind.c_str());
                }
                QVERIFY_THROWS_EXCEPTION(Error, stream->push(99));
            }
    }
};

QTEST_GUILESS_MAIN(TestModelFile)
#include "tst_modelfile.moc"
