#pragma once
// Undoable set-up or removal of the project's blind study. Participants' answers are not edits
// (ProjectDocument::recordStudyAnswer): undoing a set-up takes the answers given since along,
// and redoing it brings them back.
#include "project/ForcedChoiceStudy.h"

#include <QUndoCommand>

#include <optional>

namespace lipsync::studio {

class ProjectDocument;

class SetStudyCommand : public QUndoCommand
{
public:
    SetStudyCommand(ProjectDocument *document, std::optional<ForcedChoiceStudy> before,
                    std::optional<ForcedChoiceStudy> after, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    std::optional<ForcedChoiceStudy> m_before;
    std::optional<ForcedChoiceStudy> m_after;
};

} // namespace lipsync::studio
