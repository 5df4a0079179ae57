#pragma once
// The studio's one store of models: every AAM and dynamic model the project's references point
// at, in memory, by the reference's file (relative to the project folder). The model "in use" for
// a kind is the one of the project's latest reference of that kind (Project::model), loaded from
// its file on first use.
//
// Each Build AAM and each training gets a file of its own (reserveFile): the undo of a rebuild or
// retrain restores the reference to the previous file, and with it the previous model, everywhere
// — nothing was overwritten. A model made in a read-only document (the demo) lives here until the
// project gets a folder of its own (Save As), where every model held that the folder lacks is
// written.
//
// The forced aligners are here too: the studio's choice (the timeline's Speech menu sets it, the
// timeline's alignment and the preview's generation from new speech use it, and the Live view
// recognises with CMU Sphinx when it is CMU Sphinx) and the aligners loaded so far, which
// background tasks share.
#include "align/Aligner.h"

#include <QObject>
#include <QString>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace lipsync {
class AamModel;
class DynamicModel;
}

namespace lipsync::studio {

class ProjectDocument;

class ModelStore : public QObject
{
    Q_OBJECT
public:
    explicit ModelStore(ProjectDocument *document, QObject *parent = nullptr);
    ~ModelStore() override;

    // The AAM / dynamic model of `kind` the project uses now, or null: none referenced, or its
    // file does not load (`problem` then says which file and why).
    std::shared_ptr<const AamModel> aam(QString *problem = nullptr);
    std::shared_ptr<const DynamicModel> dynamicModel(const QString &kind, QString *problem = nullptr);
    // The identifier of the AAM in use (what a trained dynamic model records), "unspecified" without one.
    std::string aamIdentifier();
    // The AAM identifier the dynamic model of `kind` in use records (what it is written with).
    std::string recordedAamIdentifier(const QString &kind);

    // A project-relative file for a new model of `kind` ("aam" or a dynamic kind) that no model
    // held here, no reference of the project and no file beside the project has:
    // aam/faces.aam, aam/faces-2.aam, … or models/dpds.model, models/dpds-2.model, …
    QString reserveFile(const QString &kind);
    // Gives back a reserved file that was not used (a canceled or failed build or training).
    void releaseFile(const QString &file);
    // The project folder's path of `file` when the document can be written to, else empty (the
    // model then waits here for Save As).
    QString writablePath(const QString &file) const;

    // A model built or trained in this session, kept as `file`. `written`: the builder already
    // wrote it to writablePath(file); else it is written when the project gets a folder.
    void addAam(const QString &file, std::shared_ptr<const AamModel> model, bool written);
    // A dynamic model; it is written here (a small JSON file) when the document has a folder.
    // Returns the problem if writing failed (the model stays in memory), else empty.
    QString addDynamicModel(const QString &file, std::shared_ptr<const DynamicModel> model,
                            const std::string &aamIdentifier);

    // `file` is held only in memory (not yet in any project folder).
    bool isUnwritten(const std::string &file) const;

    const AlignerChoice &alignerChoice() const { return m_alignerChoice; }
    void setAlignerChoice(const AlignerChoice &choice)
    {
        m_alignerChoice = choice;
        emit alignerChoiceChanged();
    }
    // The aligners loaded so far (for background tasks: thread-safe, and kept alive by them).
    std::shared_ptr<AlignerCache> aligners() const { return m_aligners; }

signals:
    // setAlignerChoice was called (the Live view shows which recogniser its phones come from).
    void alignerChoiceChanged();
    // Models could not be written into the project's new folder (file: reason, one per line).
    void writeFailed(const QString &problems);

private:
    struct Entry
    {
        std::shared_ptr<const AamModel> aam;
        std::shared_ptr<const DynamicModel> dynamic;
        std::string aamIdentifier; // what a dynamic model is written with
        bool unwritten = false;
    };
    Entry *entryFor(const std::string &kind, QString *problem);
    bool hasWritableFolder() const;
    void onDocumentReset();
    void onLocationChanged();

    ProjectDocument *m_document;
    std::map<std::string, Entry> m_entries; // by reference file
    std::set<std::string> m_reserved;       // files handed out by reserveFile
    std::map<std::string, QString> m_failed; // files that did not load, and why
    AlignerChoice m_alignerChoice;
    std::shared_ptr<AlignerCache> m_aligners = std::make_shared<AlignerCache>();
};

} // namespace lipsync::studio
