#include "document/StudyCommands.h"

#include "document/ProjectDocument.h"

namespace lipsync::studio {

SetStudyCommand::SetStudyCommand(ProjectDocument *document, std::optional<ForcedChoiceStudy> before,
                                 std::optional<ForcedChoiceStudy> after, const QString &text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetStudyCommand::undo()
{
    // This command is the latest one applied, so the study in the document is m_after with the
    // answers recorded since: keep them for redo.
    m_after = m_document->project().study;
    m_document->applyStudy(m_before);
}

void SetStudyCommand::redo()
{
    m_document->applyStudy(m_after);
}

} // namespace lipsync::studio
