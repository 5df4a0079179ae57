#pragma once
// Training data without a project (`lipsync train --features DIR --labels DIR`): every NAME.csv in
// the features folder (core/io/FeatureCsv.h format) is paired with NAME.TextGrid (a "phones"
// tier) or NAME.lab ("start end phone", seconds or HTK units) in the labels folder; frame labels
// come from the phones by the voting rule of docs/models.md §0 at the features' frame rate, one
// per feature row. The rate is the one the CSV records ("# fps=RATE"), else `fps`.
#include "dynamics/LabelledSequence.h"

#include <string>
#include <vector>

namespace lipsync {

// Sequences sorted by name. `fps` is the rate of CSVs that record none (0: not known). Throws
// lipsync::Error naming the folder or file: no CSV files, a CSV without labels, unreadable files,
// unknown phones, a CSV that records no rate when `fps` is 0, a CSV whose recorded rate differs
// from a given `fps`.
std::vector<LabelledSequence> loadLabelledFolder(const std::string &featuresDir,
                                                 const std::string &labelsDir, double fps = 0.0);

class Project;
// Training data of a project (`--project DIR`): every sequence with both face features and a phone
// tier, in project order, labelled by the §0 vote at the sequence's own frame rate, one label per
// feature row. `projectIndex` (if given) receives each one's index in project.sequences. The
// k-fold split of `lipsync evaluate` is over this list. Throws lipsync::Error naming the manifest
// when no sequence qualifies.
std::vector<LabelledSequence> loadProjectSequences(const Project &project,
                                                   std::vector<int> *projectIndex = nullptr);

} // namespace lipsync
