#pragma once
// Undoable addition of new sequences at the end of the project's list (an imported long
// recording, one undo step however many it brings). Undo removes them from the end again and
// keeps them as they were then, for redo; their media files stay on disk for that redo.
#include "project/Sequence.h"

#include <QUndoCommand>

#include <vector>

namespace lipsync::studio {

class ProjectDocument;

class AddSequencesCommand : public QUndoCommand
{
public:
    AddSequencesCommand(ProjectDocument *document, std::vector<Sequence> sequences, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    int m_count;
    std::vector<Sequence> m_sequences; // while undone; empty while applied
};

} // namespace lipsync::studio
