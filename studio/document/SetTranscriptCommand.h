#pragma once
// Undoable edit of one sequence's transcript.
#include <QString>
#include <QUndoCommand>

namespace lipsync::studio {

class ProjectDocument;

class SetTranscriptCommand : public QUndoCommand
{
public:
    SetTranscriptCommand(ProjectDocument *document, int row, QString before, QString after);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    int m_row;
    QString m_before;
    QString m_after;
};

} // namespace lipsync::studio
