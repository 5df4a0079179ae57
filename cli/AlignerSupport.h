#pragma once
// Shared by `lipsync align` and `lipsync aligner train`: the shipped model's location and the
// pronunciation lexicon with optional project overrides.
#include "align/Lexicon.h"

#include <QString>

#include <map>
#include <memory>
#include <string>

namespace lipsync::cli {

// The default aligner model: $LIPSYNC_ALIGNER_MODEL if set; else resources/aligner/grid-s1.aligner
// searched upwards from the executable's folder (the build tree, e.g. build/release/lipsync,
// finds <source>/resources/...), then $LIPSYNC_SOURCE_DIR/resources/aligner/grid-s1.aligner,
// then <prefix>/share/lipsync/aligner/grid-s1.aligner. Empty if none exists.
QString defaultAlignerModel();

// CMU dictionary plus overrides: a project's pronunciations (Project::pronunciations), then those
// read from `overridesPath` (CMU format, "word PH ON EMES"; may be empty), which win. Throws
// lipsync::Error naming the file.
std::unique_ptr<Lexicon> makeLexicon(const QString &overridesPath,
                                     const std::map<std::string, std::string> &projectPronunciations = {});

// Media file extensions the aligner accepts in a folder.
QStringList alignerMediaFilters();

} // namespace lipsync::cli
