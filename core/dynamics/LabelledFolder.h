#pragma once
// Training data without a project (`lipsync train --features DIR --labels DIR`): every NAME.csv in
// the features folder (core/io/FeatureCsv.h format) is paired with NAME.TextGrid (a "phones"
// tier) or NAME.lab ("start end phone", seconds or HTK units) in the labels folder; frame labels
// come from the phones by the voting rule of docs/models.md §0 at `fps`, one per feature row.
#include "dynamics/LabelledSequence.h"

#include <string>
#include <vector>

namespace lipsync {

// Sequences sorted by name. Throws lipsync::Error naming the folder or file: no CSV files, a CSV
// without labels, unreadable files, unknown phones.
std::vector<LabelledSequence> loadLabelledFolder(const std::string &featuresDir,
                                                 const std::string &labelsDir, double fps);

} // namespace lipsync
