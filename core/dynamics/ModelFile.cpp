#include "dynamics/ModelFile.h"

#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/JsonEigen.h"
#include "util/PhoneSet.h"
#include "io/AtomicFile.h"
#include "util/Error.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace lipsync {

namespace {

// A compensation gain (docs/models.md §5.1): a d x d matrix, or from files that scaled each
// dimension on its own a gain per dimension, read as the diagonal matrix.
Eigen::MatrixXd compensationGain(const QJsonObject &c, const char *field, Eigen::Index d, const std::string &path)
{
    const QJsonArray values = c.value(QLatin1String(field)).toArray();
    if (!values.isEmpty() && values.first().isArray())
        return json::toMatrix(c, field, d, d, path);
    return json::toVector(c, field, d, path).asDiagonal();
}

std::unique_ptr<DynamicModel> newModelOfKind(ModelKind kind, const ModelOptions &options)
{
    switch (kind) {
    case ModelKind::HmmMean:
        return std::make_unique<HmmMeanModel>();
    case ModelKind::Brand:
        return std::make_unique<BrandModel>(options.brand);
    case ModelKind::Slds:
        return std::make_unique<SldsModel>(options.slds);
    case ModelKind::Dpds:
        return std::make_unique<DpdsModel>(options.dpds);
    }
    throw Error("unknown model kind");
}

} // namespace

ModelOptions ModelOptions::paper()
{
    ModelOptions o;
    o.compensateVariance = false;
    o.contextStates = false;
    o.brand.covariance = BrandCovariance::Diagonal;
    o.dpds.paperMode = true;
    o.dpds.optimizer = DpdsOptions::Optimizer::GradientAscent;
    o.dpds.prior = false;
    return o;
}

ModelOptions retrainingOptions(const DynamicModel &trained)
{
    ModelOptions o;
    const DynamicModel *model = &trained;
    if (const auto *context = dynamic_cast<const ContextDependentModel *>(model)) {
        o.contextStates = true;
        o.context = context->treeOptions();
        model = &context->inner();
    }
    o.compensateVariance = trained.compensatesVariance();
    // The prior's shift as the file records it: fitted to all of the person's data, which leaving
    // a few clips out hardly changes (MouthShapePrior::personShift).
    o.meanShift = trained.meanShift();
    o.priorWeight = trained.priorWeight();
    if (const auto *brand = dynamic_cast<const BrandModel *>(model))
        o.brand = brand->options();
    else if (const auto *dpds = dynamic_cast<const DpdsModel *>(model))
        o.dpds = dpds->options();
    else if (const auto *slds = dynamic_cast<const SldsModel *>(model))
        o.slds = slds->options();
    return o;
}

std::unique_ptr<DynamicModel> createDynamicModel(ModelKind kind, const ModelOptions &options)
{
    std::unique_ptr<DynamicModel> model = newModelOfKind(kind, options);
    if (options.contextStates)
        model = std::make_unique<ContextDependentModel>(std::move(model), options.context);
    model->setVarianceCompensation(options.compensateVariance);
    if (modelKindTakesPrior(kind))
        model->setMeanShift(options.meanShift, options.priorWeight);
    return model;
}

std::unique_ptr<DynamicModel> createDynamicModel(const std::string &kind, const ModelOptions &options)
{
    if (const std::optional<ModelKind> known = parseModelKind(kind))
        return createDynamicModel(*known, options);
    throw Error("unknown model kind '" + kind + "' (expected " + modelKindIdList() + ")");
}

bool modelFitsAam(const std::string &recorded, const std::string &identifier, const std::string &alias)
{
    return recorded.empty() || recorded == kUnspecifiedAam || recorded == identifier
           || (!alias.empty() && recorded == alias);
}

void saveModel(const DynamicModel &model, const std::string &path, const std::string &aamId)
{
    if (!model.isTrained())
        throw Error("cannot save an untrained " + model.kind() + " model", path);
    QJsonObject o;
    o[QStringLiteral("format")] = QString::fromLatin1(kModelFileFormat);
    o[QStringLiteral("version")] = kModelFileVersion;
    o[QStringLiteral("kind")] = QString::fromStdString(model.kind());
    o[QStringLiteral("aam")] = QString::fromStdString(aamId);
    QJsonArray labels;
    for (std::string_view name : PhoneSet::labels())
        labels.append(QString::fromLatin1(name.data(), qsizetype(name.size())));
    o[QStringLiteral("labels")] = labels;
    o[QStringLiteral("dimension")] = model.dimension();
    if (model.frameRate() > 0)
        o[QStringLiteral("frameRate")] = model.frameRate();
    if (const std::optional<AlignerChoice> &aligner = model.trainingAligner())
        o[QStringLiteral("aligner")] =
            QJsonObject{{QStringLiteral("model"), QString::fromStdString(aligner->model)},
                        {QStringLiteral("adapt"), aligner->adapt}};
    o[QStringLiteral("parameters")] = model.parametersToJson();
    if (const auto *context = dynamic_cast<const ContextDependentModel *>(&model))
        o[QStringLiteral("context")] = context->tree().toJson();
    if (model.compensatesVariance()) {
        QJsonObject c{{QStringLiteral("mean"), json::fromVector(model.compensationMean())},
                      {QStringLiteral("gain"), json::fromMatrix(model.compensationGain())}};
        if (model.compensationWindow() > 0) {
            c[QStringLiteral("window")] = model.compensationWindow();
            c[QStringLiteral("detailGain")] = json::fromMatrix(model.compensationDetailGain());
            if (model.compensationFastWindow() > 0)
                c[QStringLiteral("fastWindow")] = model.compensationFastWindow();
        }
        o[QStringLiteral("compensation")] = c;
    }
    if (model.startedFromOtherSpeakers()) {
        QJsonObject prior{{QStringLiteral("meanShift"), json::fromMatrix(model.meanShift())}};
        if (model.priorWeight() > 0)
            prior[QStringLiteral("weight")] = model.priorWeight();
        o[QStringLiteral("prior")] = prior;
    }
    writeFileAtomically(path, QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString());
}

std::unique_ptr<DynamicModel> loadModel(const std::string &path, const std::string &expectedAamId,
                                        std::string *aamId)
{
    return parseModel(readWholeFile(path), path, expectedAamId, aamId);
}

namespace {

// The file's JSON object, once it is a model file of this version.
QJsonObject modelFileObject(const std::string &text, const std::string &path)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &parseError);
    if (doc.isNull() || !doc.isObject())
        throw Error("not a model file (" + parseError.errorString().toStdString() + ")", path);
    QJsonObject o = doc.object();
    if (o.value(QStringLiteral("format")).toString() != QLatin1String(kModelFileFormat))
        throw Error("not a lipsync dynamic model file", path, "format");
    const QJsonValue version = o.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toInt() != kModelFileVersion)
        throw Error("model file version " + (version.isDouble() ? std::to_string(version.toInt()) : std::string("?"))
                        + " is not supported (this build reads version "
                        + std::to_string(kModelFileVersion) + ")",
                    path, "version");
    return o;
}

// "aligner" of a model file's object; nullopt when it records none.
std::optional<AlignerChoice> trainingAlignerOf(const QJsonObject &o, const std::string &path)
{
    if (!o.contains(QStringLiteral("aligner")))
        return std::nullopt;
    const QJsonValue aligner = o.value(QStringLiteral("aligner"));
    const QJsonValue name = aligner.toObject().value(QStringLiteral("model"));
    const QJsonValue adapt = aligner.toObject().value(QStringLiteral("adapt"));
    if (!aligner.isObject() || !name.isString() || !(adapt.isBool() || adapt.isUndefined()))
        throw Error("must be {\"model\": the aligner's model (empty: the shipped one), \"adapt\": true or false}",
                    path, "aligner");
    return AlignerChoice{name.toString().toStdString(), adapt.toBool(false)};
}

} // namespace

std::optional<AlignerChoice> modelTrainingAligner(const std::string &path)
{
    // The record alone: the parameters are read where the model is used.
    return trainingAlignerOf(modelFileObject(readWholeFile(path), path), path);
}

std::unique_ptr<DynamicModel> parseModel(const std::string &text, const std::string &path,
                                         const std::string &expectedAamId, std::string *aamId)
{
    const QJsonObject o = modelFileObject(text, path);
    const std::string aam = o.value(QStringLiteral("aam")).toString().toStdString();
    if (!expectedAamId.empty() && !modelFitsAam(aam, expectedAamId))
        throw Error("the model was trained for AAM '" + aam + "', not for AAM '" + expectedAamId + "'",
                    path, "aam");
    const QJsonArray labels = o.value(QStringLiteral("labels")).toArray();
    bool sameLabels = labels.size() == PhoneSet::kCount;
    for (int i = 0; sameLabels && i < PhoneSet::kCount; ++i)
        sameLabels = labels[i].toString().toStdString() == PhoneSet::label(i);
    if (!sameLabels)
        throw Error("the label set differs from this build's 41 phones (AA .. ZH, sil, br)", path,
                    "labels");
    const std::string kind = o.value(QStringLiteral("kind")).toString().toStdString();
    std::unique_ptr<DynamicModel> model;
    try {
        ModelOptions options;
        options.contextStates = o.contains(QStringLiteral("context"));
        model = createDynamicModel(kind, options);
    } catch (const Error &e) {
        throw Error(e.reason(), path, "kind");
    }
    if (auto *context = dynamic_cast<ContextDependentModel *>(model.get()))
        context->setTree(ContextTree::fromJson(o.value(QStringLiteral("context")).toObject(), path));
    if (!o.value(QStringLiteral("parameters")).isObject())
        throw Error("missing", path, "parameters");
    model->parametersFromJson(o.value(QStringLiteral("parameters")).toObject(), path);
    if (model->dimension() != o.value(QStringLiteral("dimension")).toInt(-1))
        throw Error("does not match the parameters", path, "dimension");
    if (o.contains(QStringLiteral("frameRate"))) {
        const double fps = o.value(QStringLiteral("frameRate")).toDouble(-1.0);
        if (!(fps > 0) || !std::isfinite(fps) || fps > 1000)
            throw Error("must be a number of frames per second in (0, 1000]", path, "frameRate");
        model->setFrameRate(fps);
    }
    model->setTrainingAligner(trainingAlignerOf(o, path));
    if (o.contains(QStringLiteral("compensation"))) {
        const QJsonObject c = o.value(QStringLiteral("compensation")).toObject();
        try {
            const bool bands = c.contains(QStringLiteral("window"));
            model->setCompensation(json::toVector(c, "mean", model->dimension(), path),
                                   compensationGain(c, "gain", model->dimension(), path),
                                   bands ? compensationGain(c, "detailGain", model->dimension(), path) : Eigen::MatrixXd(),
                                   bands ? c.value(QStringLiteral("window")).toInt(0) : 0,
                                   c.contains(QStringLiteral("fastWindow"))
                                       ? c.value(QStringLiteral("fastWindow")).toInt(-1)
                                       : 0);
        } catch (const Error &e) {
            throw Error(e.reason(), path, "compensation");
        }
    }
    if (o.contains(QStringLiteral("prior"))) {
        // Recorded, not applied again: the parameters already hold it.
        try {
            const QJsonObject prior = o.value(QStringLiteral("prior")).toObject();
            const Eigen::MatrixXd shift =
                json::toMatrix(prior, "meanShift", PhoneSet::kCount, model->dimension(), path);
            if (!shift.allFinite())
                throw Error("holds values that are not finite", path, "meanShift");
            const QJsonValue weight = prior.value(QStringLiteral("weight"));
            const bool frames = weight.isDouble() && std::isfinite(weight.toDouble()) && weight.toDouble() >= 0;
            if (!weight.isUndefined() && !frames)
                throw Error("its weight is not a number of frames >= 0", path);
            model->setMeanShift(shift, weight.toDouble(0.0));
        } catch (const Error &e) {
            throw Error(e.reason(), path, "prior");
        }
    }
    if (aamId)
        *aamId = aam;
    return model;
}

} // namespace lipsync
