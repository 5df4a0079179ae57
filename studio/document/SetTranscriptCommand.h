#pragma once
// Undoable change of one sequence's transcript and of its proposed mark
// (Sequence::transcriptProposed): a user's edit, a proposal by speech recognition, or the user's
// acceptance of a proposal. Undo restores both.
#include <QString>
#include <QUndoCommand>

#include <vector>

namespace lipsync::studio {

class ProjectDocument;

// A sequence's transcript as the command sets it.
struct TranscriptState
{
    QString text;
    bool proposed = false; // by speech recognition, not checked by the user yet
    std::vector<double> confidence; // of a proposal: each word's posterior (Sequence::transcriptConfidence)
    bool operator==(const TranscriptState &) const = default;
};

class SetTranscriptCommand : public QUndoCommand
{
public:
    // What the step is called in the Edit menu.
    enum class Kind { Edit, Propose, Accept };

    SetTranscriptCommand(ProjectDocument *document, int row, TranscriptState before, TranscriptState after, Kind kind);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    int m_row;
    TranscriptState m_before;
    TranscriptState m_after;
};

} // namespace lipsync::studio
