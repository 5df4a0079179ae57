#pragma once
// The one project document. A project is a folder:
//   project.json          versioned manifest (sequences, tiers, landmarks, model references)
//   project.json.bak      the previous manifest, kept by every save
//   features/<id>.csv     per-sequence features (frame index, then the parameters)
//   media/ aam/ models/   media, built AAMs and trained models (referenced by relative path)
// Load validates everything and throws lipsync::Error naming the file and the field
// ("project.json: sequences[2].frameRate: must be positive"). Save is atomic per file
// (QSaveFile), so a crash leaves either the old or the new version.
#include "project/Sequence.h"

#include <string>
#include <vector>

namespace lipsync {

// A built AAM or trained dynamic model the project refers to.
struct ModelReference
{
    std::string kind; // "aam", "aligner", "dpds", "slds", "brand", "hmm"
    std::string name; // user-visible name
    std::string file; // relative to the project folder
    bool operator==(const ModelReference &) const = default;
};

class Project
{
public:
    static constexpr int kFormatVersion = 1;
    static constexpr const char *kManifestName = "project.json";

    Project() = default;

    // Reads <folder>/project.json and the files it references. Throws lipsync::Error.
    static Project load(const std::string &folder);
    // Writes the manifest and the feature files into `folder` (created if missing), keeping the
    // previous manifest as project.json.bak. Throws lipsync::Error on I/O failure.
    void save(const std::string &folder) const;
    void save() const { save(m_folder); }

    // Creates a project from a folder of media files (*.mpg, *.mp4, *.mov, *.avi, *.wav),
    // probing each for frame rate and count and reading a transcript and word tier from a
    // sibling <stem>.align / .lab / .txt when present.
    static Project fromMediaFolder(const std::string &mediaFolder, const std::string &projectFolder);

    const std::string &folder() const { return m_folder; }
    void setFolder(const std::string &folder) { m_folder = folder; }
    // Absolute path of a file referenced relative to the project folder.
    std::string resolve(const std::string &relative) const;

    std::string name;
    std::vector<Sequence> sequences;
    std::vector<ModelReference> models;

    Sequence *sequence(const std::string &id);
    const Sequence *sequence(const std::string &id) const;

    bool operator==(const Project &other) const; // content, not folder

private:
    std::string m_folder;
};

} // namespace lipsync
