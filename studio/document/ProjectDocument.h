#pragma once
// The open project as the studio edits it: the core document, where it lives, and the
// request* edit functions. Each request either changes nothing and returns false, or pushes
// one command on the main window's undo stack (the studio's single undo mechanism); the
// commands call the apply* functions, which emit what changed so views refresh only that.
#include "project/Project.h"

#include <QObject>
#include <QString>

#include <optional>
#include <vector>

class QUndoStack;

namespace lipsync::studio {

struct TierPair;
struct TranscriptState;

class ProjectDocument : public QObject
{
    Q_OBJECT
public:
    ProjectDocument(QUndoStack *undoStack, QObject *parent = nullptr);

    const Project &project() const { return m_project; }
    // The folder the project was loaded from or last saved to.
    QString folder() const { return m_folder; }
    // The bundled demo is never written to: saving it asks for a new folder.
    bool isReadOnly() const { return m_readOnly; }
    bool isOpen() const { return m_open; }
    bool isModified() const;
    // Where export and save dialogs start: beside the project (its folder), or for the read-only
    // demo or no project the folder Save As suggests for projects (~/lipsync-projects).
    QString exportFolder() const;

    // Replaces the whole document (open, new). Clears the undo stack.
    void reset(Project project, const QString &folder, bool readOnly);
    // The document differs from its files though nothing was edited (a recovered autosave): the
    // undo stack has no clean state until the next save.
    void markUnsaved();
    // Writes the project into `folder` (Project::saveAs: relative paths rebased so they still
    // reach the media). Saving the read-only demo copies its clips along instead. Throws
    // lipsync::Error. On success the document lives in `folder`.
    void saveTo(const QString &folder);

    int sequenceCount() const { return int(m_project.sequences.size()); }
    const Sequence &sequence(int row) const { return m_project.sequences.at(std::size_t(row)); }
    QString mediaPath(int row) const;

    // New sequences (an imported long recording, AddSequencesCommand) appended to the list as one
    // undo step; the undo removes them from its end again. Rows before them never move. Refused
    // (false) when there are none, an id is taken or they would not load again.
    bool requestAddSequences(std::vector<Sequence> sequences, const QString &text);
    void applyAddSequences(std::vector<Sequence> sequences);
    // Removes the last `count` sequences and returns them (for redo), as they are now.
    std::vector<Sequence> applyRemoveLastSequences(int count);

    // Transcripts (SetTranscriptCommand), each request one undo step. The user's edit (the
    // sequence list's Transcript column): whitespace simplified, and the transcript no longer
    // proposed. A proposal by speech recognition: the words marked proposed (not checked by the
    // user; Sequence::transcriptProposed). Accepting a proposal: the same words, the mark cleared.
    // False when nothing would change (accepting a transcript that is not proposed included).
    bool requestTranscriptChange(int row, const QString &transcript);
    // `confidence`: the recogniser's posterior of each proposed word (or empty).
    bool requestProposedTranscript(int row, const QString &transcript, std::vector<double> confidence = {});
    bool requestAcceptTranscript(int row);
    void applyTranscript(int row, const TranscriptState &state);

    // Speech (timeline/TierCommands): the word and phone tiers of one sequence (alignment,
    // timeline edits). Requests with the same mergeKey >= 0 (one boundary drag) merge into one
    // undo step; `text` names it.
    // The transcript's fit stays as it is; requestAlignedTiers sets the tiers and the fit their
    // alignment measured (none: not measured).
    bool requestTiersChange(int row, const Tier &words, const Tier &phones, const QString &text, int mergeKey = -1);
    bool requestAlignedTiers(int row, const TierPair &aligned, const QString &text);
    void applyTiers(int row, const TierPair &tiers);

    // Speech (timeline/PronunciationCommand): the project's pronunciation overrides, word ->
    // ARPAbet phones (Project::pronunciations), replaced as a whole; false if unchanged.
    bool requestPronunciations(const std::map<std::string, std::string> &pronunciations, const QString &text);
    void applyPronunciations(const std::map<std::string, std::string> &pronunciations);

    // Animation (export/MouthShapesDialog, MouthShapesCommand): the user's own mouth shapes for
    // cue export (Project::mouthShapes), replaced as a whole; false if unchanged.
    bool requestMouthShapes(const std::map<std::string, Project::MouthShapeFeatures> &shapes, const QString &text,
                            int mergeKey = -1);
    void applyMouthShapes(const std::map<std::string, Project::MouthShapeFeatures> &shapes);

    // Faces (annotate/LandmarkCommands). The landmarks of one frame (nullopt: none); `text` names
    // the undo step.
    bool requestLandmarks(int row, int frame, const std::optional<LandmarkSet> &landmarks, const QString &text);
    void applyLandmarks(int row, int frame, const std::optional<LandmarkSet> &landmarks);
    // Whole sequences' landmarks and features at once (tracking), as one undo step.
    struct FaceData
    {
        int row = -1;
        std::map<int, LandmarkSet> landmarks;
        Eigen::MatrixXd features;
        std::vector<double> fitErrors; // per frame (Sequence::fitErrors)
    };
    bool requestFaces(const std::vector<FaceData> &faces, const QString &text);
    void applyFaces(const std::vector<FaceData> &faces);
    // Adds (or replaces, same kind and name) a model reference.
    bool requestAddModel(const ModelReference &model, const QString &text);
    void applyModels(const std::vector<ModelReference> &models);

    // Blind study (compare/StudyCommands). Sets up or removes (nullopt) the study, one undo step.
    bool requestStudy(const std::optional<ForcedChoiceStudy> &study, const QString &text);
    void applyStudy(const std::optional<ForcedChoiceStudy> &study);
    // A participant's session. Participants and answers are data, not edits: they never go on
    // the undo stack (Ctrl+Z must not drop a participant's answer). In a saved project each is
    // written to the study file at once (Project::saveStudy), so nothing is lost if the studio
    // dies mid-session and the document stays unmodified; otherwise the document is modified
    // until the next save writes them. Returns the session index; throws lipsync::Error (no
    // study, bad index, I/O).
    int addStudyParticipant(const QString &participant);
    void recordStudyAnswer(int session, int trial, StudyChoice choice, double seconds);
    // The study is on disk as it is in memory (saved project folder, nothing unsaved).
    bool isStudySaved() const;

signals:
    void documentReset();
    void sequenceChanged(int row);
    // Rows [first, first + count) around applyAddSequences and applyRemoveLastSequences, before
    // and after the list changes (as QAbstractItemModel's begin/end rows, for the sequence list).
    void sequencesAboutToBeAdded(int first, int count);
    void sequencesAdded(int first, int count);
    void sequencesAboutToBeRemoved(int first, int count);
    void sequencesRemoved(int first, int count);
    void modelsChanged();
    void studyChanged();
    void pronunciationsChanged();
    void mouthShapesChanged();
    void locationChanged();
    // An edit was refused because it would have left the document unsaveable (a defect of the
    // edit, not of the user's input): `edit` names it, `why` says what was wrong.
    void editRefused(const QString &edit, const QString &why);

private:
    void refuse(const QString &edit, const QString &why);
    bool pushTiers(int row, TierPair after, const QString &text, int mergeKey);
    void recordStudyData(ForcedChoiceStudy study);

    QUndoStack *m_undo;
    Project m_project;
    QString m_folder;
    bool m_readOnly = false;
    bool m_open = false;
    bool m_unsavedStudyData = false; // study data recorded while the study file could not take it
};

} // namespace lipsync::studio
