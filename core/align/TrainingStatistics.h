#pragma once
// The statistics of one part of an aligner training, for training on many machines as HTK's
// HERest -p does (`lipsync aligner train --accumulate-only`, then `--merge`; AlignerTrainer):
//   - flat-start statistics (FlatStartStatistics) with the feature options they were computed
//     under, or
//   - one Baum-Welch pass's accumulators (Accumulators) with the model they were collected under.
// Merging sums the parts and checks that they share the features or the model.
//
// File (binary, little-endian; docs/formats.md): "LSTATS01", u32 kind (1 flat start, 2 Baum-Welch),
// u64 length and the text of the model (AcousticModel::parse; for a flat start a model of the
// feature options only), then
//   flat start: i64 frames[2], u32 dimension D, f64 sum[0][D], sumSquares[0][D], sum[1][D],
//               sumSquares[1][D];
//   Baum-Welch: f64 log-likelihood, i64 frames, i32 utterances, then for every state of the model
//               f64 occupancy, f64 self-transition count and, for its M components, f64
//               occupancy[M], sum[M][D], sumSquares[M][D].
#include "align/AcousticModel.h"
#include "align/AlignerTrainer.h"
#include "align/BaumWelch.h"

#include <optional>
#include <string>
#include <vector>

namespace lipsync {

struct TrainingStatistics
{
    enum class Kind { FlatStart = 1, BaumWelch = 2 };
    Kind kind = Kind::FlatStart;
    // Baum-Welch: the model the statistics were collected under; flat start: a model holding the
    // feature options (AlignerTrainer's featureModel) whose flat start they make.
    AcousticModel model;
    FlatStartStatistics flatStart;
    std::optional<Accumulators> baumWelch;

    // Adds `other` (same kind and model); throws lipsync::Error otherwise.
    void add(const TrainingStatistics &other);
};

void writeTrainingStatistics(const std::string &path, const TrainingStatistics &statistics);
// Throws lipsync::Error naming `path` for a damaged or truncated file.
TrainingStatistics readTrainingStatistics(const std::string &path);
TrainingStatistics parseTrainingStatistics(const std::string &bytes, const std::string &path);

} // namespace lipsync
