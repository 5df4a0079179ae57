#pragma once
// Undoable face edits: one frame's landmarks (a click, a whole drag, copy-previous, a detection),
// whole sequences' tracked landmarks and features, and the project's model references.
#include "document/ProjectDocument.h"

#include <QUndoCommand>

#include <optional>
#include <vector>

namespace lipsync::studio {

class SetLandmarksCommand : public QUndoCommand
{
public:
    SetLandmarksCommand(ProjectDocument *document, int row, int frame, std::optional<LandmarkSet> before,
                        std::optional<LandmarkSet> after, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    int m_row;
    int m_frame;
    std::optional<LandmarkSet> m_before;
    std::optional<LandmarkSet> m_after;
};

class SetFacesCommand : public QUndoCommand
{
public:
    SetFacesCommand(ProjectDocument *document, std::vector<ProjectDocument::FaceData> before,
                    std::vector<ProjectDocument::FaceData> after, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    std::vector<ProjectDocument::FaceData> m_before;
    std::vector<ProjectDocument::FaceData> m_after;
};

class SetModelsCommand : public QUndoCommand
{
public:
    SetModelsCommand(ProjectDocument *document, std::vector<ModelReference> before,
                     std::vector<ModelReference> after, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    std::vector<ModelReference> m_before;
    std::vector<ModelReference> m_after;
};

} // namespace lipsync::studio
