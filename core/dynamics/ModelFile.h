#pragma once
// Model files and the model factory. A model file is JSON (written atomically):
//   {"format": "lipsync-dynamic-model", "version": 1, "kind": "dpds", "aam": "<AAM id>",
//    "labels": ["AA", ..., "sil", "br"], "dimension": 32, "parameters": {...}}
// "labels" records the phone set the integer labels refer to, "aam" the AAM whose parameters
// the features are, "frameRate" (optional) the frames per second it was trained at. A model over context-dependent states (§5.2) adds "context" (ContextTree's
// JSON); its parameters are then indexed by the tree's states. A model started from other speakers
// (§5.4) records the shift its means were moved by and the weight that made it ("prior": {"meanShift": 41 x d, "weight"}). Loading rejects another format or version, an unknown kind, another label
// set, and (when an AAM id is expected) another AAM, with a lipsync::Error naming the file.
// "aligner" (optional): {"model", "adapt"}, the aligner whose phones it was trained on
// (DynamicModel::trainingAligner).
#include "dynamics/BrandModel.h"
#include "dynamics/ContextTree.h"
#include "dynamics/DpdsModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/ModelKind.h"
#include "dynamics/SldsModel.h"

#include <memory>
#include <optional>
#include <string>

namespace lipsync {

constexpr int kModelFileVersion = 1;
constexpr const char *kModelFileFormat = "lipsync-dynamic-model";

struct ModelOptions
{
    BrandOptions brand;
    SldsOptions slds;
    DpdsOptions dpds;
    // Every kind: variance compensation of the generated trajectories (DynamicModel, §5.1).
    bool compensateVariance = false;
    // Every kind: context-dependent states tied by decision trees (ContextDependentModel, §5.2).
    bool contextStates = false;
    ContextTreeOptions context;
    // Kinds that take a prior (modelKindTakesPrior): each phone's mean moves by this row once
    // fitted (41 x d, DynamicModel::setMeanShift; MouthShapePrior::personShift). Empty: none.
    Eigen::MatrixXd meanShift;
    double priorWeight = 0; // the weight in frames that made meanShift, recorded in the file

    // The paper's models exactly, as far as they are well defined (docs/models.md §8, the paper
    // preset): no variance compensation, no phones in context, Brand with diagonal covariances,
    // the DPDS by Algorithm 1 (unit weights, paper mode) and gradient ascent with
    // maximum-likelihood start variances (no §4.5 prior). Its ridge and the bound on a stay: see §8.
    static ModelOptions paper();
};

// The options that train a model like `trained` on other data: its kind's options as the model
// holds them (what its file records), its context states, variance compensation and prior shift.
ModelOptions retrainingOptions(const DynamicModel &trained);

std::unique_ptr<DynamicModel> createDynamicModel(ModelKind kind, const ModelOptions &options = {});
// A kind by its id (ModelKind.h); throws lipsync::Error for an unknown id.
std::unique_ptr<DynamicModel> createDynamicModel(const std::string &kind,
                                                 const ModelOptions &options = {});

// The AAM contract of model files (docs/formats.md): a model records the AAM whose parameters it
// generates, by that AAM's identifier; models the studio trained before identifiers existed record
// its name in the project (pass it as `alias`); a model trained from bare feature files records
// none ("unspecified", or empty) and fits any AAM with as many parameters. Whether a model that
// records `recorded` may drive the AAM `identifier`. The one rule of loadModel, render, Live and
// the study.
bool modelFitsAam(const std::string &recorded, const std::string &identifier, const std::string &alias = {});
// The identifier a model records when its AAM is not known.
inline constexpr const char *kUnspecifiedAam = "unspecified";

void saveModel(const DynamicModel &model, const std::string &path, const std::string &aamId);
// expectedAamId empty: accept any AAM; else a model that does not fit it (modelFitsAam) is refused.
// aamId (optional) receives the file's AAM id.
std::unique_ptr<DynamicModel> loadModel(const std::string &path,
                                        const std::string &expectedAamId = {},
                                        std::string *aamId = nullptr);
// The aligner the model at `path` was trained with (DynamicModel::trainingAligner), read without
// the parameters; throws as loadModel for a file that is not a model file or a malformed record.
std::optional<AlignerChoice> modelTrainingAligner(const std::string &path);
// The same from the file's text; `pathForErrors` only names the source in errors.
std::unique_ptr<DynamicModel> parseModel(const std::string &text, const std::string &pathForErrors,
                                         const std::string &expectedAamId = {},
                                         std::string *aamId = nullptr);

} // namespace lipsync
