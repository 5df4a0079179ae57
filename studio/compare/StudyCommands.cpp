#include "compare/StudyCommands.h"

#include "app/ProjectDocument.h"

namespace lipsync::studio {

SetStudyCommand::SetStudyCommand(ProjectDocument *document, std::optional<ForcedChoiceStudy> before,
                                 std::optional<ForcedChoiceStudy> after, const QString &text, int mergeKey)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after)), m_mergeKey(mergeKey)
{
    setText(text);
}

void SetStudyCommand::undo()
{
    m_document->applyStudy(m_before);
}

void SetStudyCommand::redo()
{
    m_document->applyStudy(m_after);
}

bool SetStudyCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetStudyCommand *>(other);
    if (next->m_mergeKey != m_mergeKey)
        return false;
    m_after = next->m_after;
    return true;
}

} // namespace lipsync::studio
