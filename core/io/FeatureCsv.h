#pragma once
// Per-frame feature files: one row per video frame, the frame index then the d parameters,
// comma separated, with a header line "frame,p0,p1,...". This is what `lipsync track` writes
// and what `lipsync train --features DIR` reads.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

struct FeatureTable
{
    std::vector<int> frames;  // frame index of each row
    Eigen::MatrixXd values;   // rows x d
};

// Throws lipsync::Error naming the file and line for ragged rows, non-numbers, NaN/inf values.
FeatureTable readFeatureCsv(const std::string &path);
// The same from the file's text; `pathForErrors` only names the source in errors.
FeatureTable parseFeatureCsv(const std::string &text, const std::string &pathForErrors = {});
// Atomic (written to a temporary file, then renamed). Rows are numbered 0..rows-1 unless
// `frames` is given.
void writeFeatureCsv(const std::string &path, const Eigen::MatrixXd &values,
                     const std::vector<int> &frames = {});

} // namespace lipsync
