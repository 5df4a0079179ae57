#include "document/TierCommands.h"

#include "document/ProjectDocument.h"

namespace lipsync::studio {

SetTiersCommand::SetTiersCommand(ProjectDocument *document, int row, TierPair before, TierPair after,
                                 const QString &text, int mergeKey)
    : m_document(document), m_row(row), m_before(std::move(before)), m_after(std::move(after)), m_mergeKey(mergeKey)
{
    setText(text);
}

void SetTiersCommand::undo()
{
    m_document->applyTiers(m_row, m_before);
}

void SetTiersCommand::redo()
{
    m_document->applyTiers(m_row, m_after);
}

bool SetTiersCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = dynamic_cast<const SetTiersCommand *>(other);
    if (!next || next->m_row != m_row || next->m_mergeKey != m_mergeKey || m_mergeKey < 0)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

} // namespace lipsync::studio
