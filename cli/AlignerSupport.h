#pragma once
// Shared by the commands that align or train the aligner: the shipped model's location, the
// pronunciation lexicon with optional project overrides, and a folder of transcribed recordings.
#include "Command.h"

#include "align/AlignerTrainer.h"
#include "align/Lexicon.h"

#include <QJsonArray>
#include <QString>

#include <map>
#include <memory>
#include <string>

namespace lipsync::cli {

// The default aligner model (align/ShippedAlignerModel): $LIPSYNC_ALIGNER_MODEL if set, else the
// shipped aligner/grid-s1.aligner (util/ResourceLocator). Empty if none exists.
QString defaultAlignerModel();
// The model a command uses: `given` (its --model) if not empty, else defaultAlignerModel().
// Throws lipsync::Error naming `command` when there is none.
QString alignerModelOrDefault(const QString &given, const QString &command);

// CMU dictionary plus overrides: a project's pronunciations (Project::pronunciations), then those
// read from `overridesPath` (CMU format, "word PH ON EMES"; may be empty), which win. Throws
// lipsync::Error naming the file.
std::unique_ptr<Lexicon> makeLexicon(const QString &overridesPath,
                                     const std::map<std::string, std::string> &projectPronunciations = {});

// --pronunciations DICT: the CMU-format dictionary makeLexicon() reads.
CommandOption pronunciationsOption();
// --media DIR, --transcripts DIR and --pronunciations DICT: what loadTranscribedFolder() reads.
std::vector<CommandOption> transcribedFolderOptions();

// The transcribed recordings of a folder (`aligner train`, `adapt`, `calibrate`): every media file in
// `mediaDir` (io/MediaFolder) with a transcript of the same name in `transcriptDir`, decoded and
// turned into features as `model` computes them, in parallel.
// Recordings that cannot be used (no transcript, unknown words, undecodable or silent audio) go
// to `skipped` ({id, reason}), also printed to stderr unless `quiet`. Throws lipsync::Error naming
// the folder when either folder does not exist or the media folder has no media files.
// With `shards` > 1 only every shards-th recording from the shard-th (0-based) is used.
std::vector<TrainingUtterance> loadTranscribedFolder(const QString &mediaDir, const QString &transcriptDir,
                                                     const AcousticModel &model, const Lexicon &lexicon,
                                                     bool quiet, QJsonArray &skipped, int shard = 0, int shards = 1);

} // namespace lipsync::cli
