#pragma once
// project.json, format "lipsync-project" (version Project::kFormatVersion; version 1 manifests are
// read too): conversion between a Project and its manifest with field-by-field validation. Every
// error names the manifest and the field path ("sequences[2].frameRate"). See Project.h for the
// folder layout and docs/formats.md for the schema.
#include "project/Project.h"

#include <QByteArray>
#include <QJsonObject>

#include <string>

namespace lipsync {

class ProjectManifest
{
public:
    static constexpr const char *kFormatName = "lipsync-project";

    // The manifest of `project` as it is written into `targetFolder`: relative media and model
    // paths are rebased from project.folder() to targetFolder so they keep pointing at the same
    // files, and each sequence with features refers to features/<id>.csv.
    static QJsonObject toJson(const Project &project, const std::string &targetFolder);
    // Indented JSON in the manifest's key order, with short arrays and flat objects on one line
    // (a landmark frame is one line, not 100).
    static QByteArray serialize(const QJsonObject &manifest);

    // Parses and validates manifest text. `manifestPath` is used in errors; relative feature
    // paths resolve against `folder`. With `readFeatures` false the feature files are not opened
    // (used by save to validate what it is about to write).
    static Project parse(const QByteArray &text, const std::string &manifestPath,
                         const std::string &folder, bool readFeatures = true);
    static Project fromJson(const QJsonObject &manifest, const std::string &manifestPath,
                            const std::string &folder, bool readFeatures = true);

    // Where features of sequence `id` live inside a project folder.
    static std::string featureFileName(const std::string &id) { return "features/" + id + ".csv"; }
};

// `path` relative to `fromFolder`, re-expressed relative to `toFolder`; absolute paths are kept.
std::string rebaseRelativePath(const std::string &path, const std::string &fromFolder,
                               const std::string &toFolder);

} // namespace lipsync
