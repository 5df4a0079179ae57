#include "document/AddSequencesCommand.h"

#include "document/ProjectDocument.h"

#include <utility>

namespace lipsync::studio {

AddSequencesCommand::AddSequencesCommand(ProjectDocument *document, std::vector<Sequence> sequences,
                                         const QString &text)
    : m_document(document), m_count(int(sequences.size())), m_sequences(std::move(sequences))
{
    setText(text);
}

void AddSequencesCommand::undo()
{
    // The later commands are undone already: the last m_count sequences are this command's.
    m_sequences = m_document->applyRemoveLastSequences(m_count);
}

void AddSequencesCommand::redo()
{
    m_document->applyAddSequences(std::exchange(m_sequences, {}));
}

} // namespace lipsync::studio
