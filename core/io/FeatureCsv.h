#pragma once
// Per-frame feature files: one row per video frame, the frame index then the d parameters,
// comma separated, with a header line "frame,p0,p1,...". This is what `lipsync track` writes
// and what `lipsync train --features DIR` reads.
// Lines starting with '#' are comments. A comment "# fps=RATE" (written first, before the
// header) records the video frame rate the rows were sampled at, which phone labels in seconds
// need; files without it (older ones) stay readable and report no rate.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

struct FeatureTable
{
    std::vector<int> frames;  // frame index of each row
    Eigen::MatrixXd values;   // rows x d
    double frameRate = 0.0;   // frames per second from "# fps=RATE"; 0: the file records none
};

// Throws lipsync::Error naming the file and line for ragged rows, non-numbers, NaN/inf values,
// an fps comment that is not a positive finite number or that repeats.
FeatureTable readFeatureCsv(const std::string &path);
// The same from the file's text; `pathForErrors` only names the source in errors.
FeatureTable parseFeatureCsv(const std::string &text, const std::string &pathForErrors = {});
// The file's text. Rows are numbered 0..rows-1 unless `frames` is given. Values, and a
// frameRate > 0 recorded as "# fps=RATE", are written as the shortest decimal that reads back
// exactly. `pathForErrors` only names the destination in errors.
std::string formatFeatureCsv(const Eigen::MatrixXd &values, const std::vector<int> &frames = {},
                             double frameRate = 0.0, const std::string &pathForErrors = {});
// formatFeatureCsv's text, written atomically (a temporary file, then renamed).
void writeFeatureCsv(const std::string &path, const Eigen::MatrixXd &values,
                     const std::vector<int> &frames = {}, double frameRate = 0.0);

} // namespace lipsync
