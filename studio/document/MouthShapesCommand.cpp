#include "document/MouthShapesCommand.h"

#include "document/ProjectDocument.h"

namespace lipsync::studio {

SetMouthShapesCommand::SetMouthShapesCommand(ProjectDocument *document, Shapes before, Shapes after,
                                             const QString &text, int mergeKey)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after)), m_mergeKey(mergeKey)
{
    setText(text);
}

void SetMouthShapesCommand::undo()
{
    m_document->applyMouthShapes(m_before);
}

void SetMouthShapesCommand::redo()
{
    m_document->applyMouthShapes(m_after);
}

bool SetMouthShapesCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetMouthShapesCommand *>(other);
    if (next->m_mergeKey != m_mergeKey)
        return false;
    m_after = next->m_after;
    return true;
}

} // namespace lipsync::studio
