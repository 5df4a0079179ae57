#pragma once
// The one project document. A project is a folder:
//   project.json          versioned manifest (sequences, tiers, landmarks, model references)
//   project.json.bak      the previous manifest, kept by every save
//   features/<id>.csv     per-sequence features (frame index, then the parameters)
//   media/ aam/ models/   media, built AAMs and trained models (referenced by relative path)
//   study.json            the blind forced-choice study with every participant's answers
//                         (ForcedChoiceStudy's own versioned format), when the project has one
// Load validates everything and throws lipsync::Error naming the file and the field
// (".../project.json: sequences[2].frameRate: must be a positive number"). Missing media is not
// a load error (it may be on another disk; see mediaPath), a missing features file is. Save is
// atomic per file (QSaveFile), so a crash leaves either the old or the new version. The manifest
// format is read and written by ProjectManifest.
#include "project/ForcedChoiceStudy.h"
#include "project/Sequence.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

// A built AAM or trained dynamic model the project refers to.
struct ModelReference
{
    std::string kind; // "aam", "aligner" or a dynamic model kind's id (dynamics/ModelKind.h)
    std::string name; // user-visible name
    std::string file; // relative to the project folder
    bool operator==(const ModelReference &) const = default;
};

class Project
{
public:
    // 2: sequences may carry per-frame fitErrors; 3: and transcriptProposed; 4: and transcriptFit,
    // and the project its aligner; 5: and the user's mouth shapes for cue export; 6: and the
    // threshold of the aligner that measured a transcriptFit. Older manifests still load.
    static constexpr int kFormatVersion = 6;
    static constexpr const char *kManifestName = "project.json";
    static constexpr const char *kStudyFileName = "study.json";

    Project() = default;

    // Reads <folder>/project.json and the feature files it references. `folder` may also be the
    // path of the manifest itself. folder() becomes the absolute folder. Throws lipsync::Error.
    static Project load(const std::string &folder);
    // Writes the manifest and the feature files into `folder` (created if missing), keeping the
    // previous manifest as project.json.bak. The content is validated first, so a project that
    // would not load again (NaN features, a bad frame rate, ...) is not written. Throws
    // lipsync::Error on invalid content or I/O failure; the old files stay then.
    // Saving into a folder other than folder() writes only the manifest and the features there;
    // relative media and model paths are rewritten relative to the new folder so they still
    // point at the same files (media is never copied), absolute paths stay absolute. The object
    // itself is unchanged: use saveAs to move it to the new folder.
    void save(const std::string &folder) const;
    // The checks of load, on the content in memory, without touching the disk: throws
    // lipsync::Error naming the manifest and the field of the first thing that would not load
    // again (an overlapping interval, NaN features, a bad frame rate, ...). save runs them first.
    void validate() const { validate(m_folder.empty() ? std::string(".") : m_folder); }
    void save() const { save(m_folder); }
    // save(folder), then the project lives in `folder`: relative paths rebased, folder() set.
    void saveAs(const std::string &folder);

    // Creates a project (not yet saved) in `projectFolder` from a folder of media files (*.mpg,
    // *.mp4, *.mov, *.avi, *.mkv, *.wav; sorted by name, id = file stem), probing each for frame
    // rate and count and reading a transcript and word tier from a sibling <stem>.align (GRID
    // word timings), a plain-text transcript <stem>.lab / <stem>.txt or the spoken words of
    // subtitles <stem>.srt / <stem>.vtt when present. Media paths
    // are relative to projectFolder. Audio-only files get kAudioOnlyFrameRate. A clip that cannot
    // be read (damaged, truncated, no usable frame rate, an unreadable transcript) is left out and
    // listed in `skipped` ("file: reason"); with `skipped` null, it throws lipsync::Error naming
    // the file instead. Throws when no clip is left.
    static Project fromMediaFolder(const std::string &mediaFolder, const std::string &projectFolder,
                                   std::vector<std::string> *skipped = nullptr);
    // The frame grid of sequences without video (features are still per frame).
    static constexpr double kAudioOnlyFrameRate = 25.0;

    const std::string &folder() const { return m_folder; }
    void setFolder(const std::string &folder) { m_folder = folder; }
    // Absolute path of a file referenced relative to the project folder.
    std::string resolve(const std::string &relative) const;
    std::string mediaPath(const Sequence &sequence) const { return resolve(sequence.mediaFile); }
    // The manifest path inside folder() (or `folder`).
    std::string manifestPath() const { return manifestPath(m_folder); }
    static std::string manifestPath(const std::string &folder);

    std::string name;
    std::vector<Sequence> sequences;
    std::vector<ModelReference> models;
    // The blind study (paper §4, Table 1), saved with the project as study.json.
    std::optional<ForcedChoiceStudy> study;

    // Writes only study.json into folder() (atomically), so a participant's answer is on disk
    // right after each trial without rewriting the manifest and features. The manifest must
    // already refer to the study (the project was saved with it); throws lipsync::Error if the
    // project has no folder or no study.
    void saveStudy() const;
    std::string studyPath() const { return resolve(kStudyFileName); }

    // Pronunciation overrides for the aligner, before the CMU dictionary and espeak-ng: word
    // (lower case, no spaces) -> ARPAbet phones of PhoneSet separated by spaces ("L IH1 P S IH2 NG K";
    // stress digits allowed). Every alignment of the project uses them.
    std::map<std::string, std::string> pronunciations;

    // Whose aligner the project's speech is aligned with when it names no aligner model of its
    // own (a model reference of kind "aligner", which always wins): kBuiltinAligner, the shipped
    // model of GRID's speaker s1 (also when empty: projects that never said, the demo among
    // them), or kGenericAligner, CMU Sphinx's US-English model adapted to the recording's speaker:
    // the right start for anyone else, and what new projects say.
    std::string aligner;
    static constexpr const char *kBuiltinAligner = "builtin";
    static constexpr const char *kGenericAligner = "generic";
    bool alignsGeneric() const { return aligner == kGenericAligner && !model("aligner"); }

    // The user's own picture of mouth shapes for cue export (animation/MouthMapping): a Rhubarb
    // shape's letter ("A".."H") -> its opening, width, rounding and teeth showing, each 0..1 in
    // the range of this person's frames. A shape not listed is learned from the frames.
    using MouthShapeFeatures = std::array<double, 4>;
    std::map<std::string, MouthShapeFeatures> mouthShapes;

    Sequence *sequence(const std::string &id);
    const Sequence *sequence(const std::string &id) const;
    // The reference of `kind` ("aam", "dpds", ...) the project uses, or null: the latest one, as a
    // model added again under another name supersedes the earlier (ProjectDocument::requestAddModel).
    const ModelReference *model(const std::string &kind) const;
    // The AAM the project uses (model("aam")): the one whose parameters its features are.
    const ModelReference *aam() const { return model(kAamKind); }
    // The path of that AAM's file; throws lipsync::Error naming the manifest when there is none.
    std::string aamPath() const;
    static constexpr const char *kAamKind = "aam";

    bool operator==(const Project &other) const; // content, not folder

private:
    // validate() as the project would be written into `folder`.
    void validate(const std::string &folder) const;

    std::string m_folder;
};

} // namespace lipsync
