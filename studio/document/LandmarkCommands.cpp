#include "document/LandmarkCommands.h"

namespace lipsync::studio {

SetLandmarksCommand::SetLandmarksCommand(ProjectDocument *document, int row, int frame,
                                         std::optional<LandmarkSet> before, std::optional<LandmarkSet> after,
                                         const QString &text)
    : m_document(document), m_row(row), m_frame(frame), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetLandmarksCommand::undo()
{
    m_document->applyLandmarks(m_row, m_frame, m_before);
}

void SetLandmarksCommand::redo()
{
    m_document->applyLandmarks(m_row, m_frame, m_after);
}

SetFacesCommand::SetFacesCommand(ProjectDocument *document, std::vector<ProjectDocument::FaceData> before,
                                 std::vector<ProjectDocument::FaceData> after, const QString &text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetFacesCommand::undo()
{
    m_document->applyFaces(m_before);
}

void SetFacesCommand::redo()
{
    m_document->applyFaces(m_after);
}

SetModelsCommand::SetModelsCommand(ProjectDocument *document, std::vector<ModelReference> before,
                                   std::vector<ModelReference> after, const QString &text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetModelsCommand::undo()
{
    m_document->applyModels(m_before);
}

void SetModelsCommand::redo()
{
    m_document->applyModels(m_after);
}

} // namespace lipsync::studio
