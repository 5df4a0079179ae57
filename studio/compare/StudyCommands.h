#pragma once
// Undoable change of the project's blind study (set-up, removal, a participant's answers).
// Commands with the same merge key >= 0 merge into one undo step.
#include "project/ForcedChoiceStudy.h"

#include <QUndoCommand>

#include <optional>

namespace lipsync::studio {

class ProjectDocument;

class SetStudyCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x5374; // "St"

    SetStudyCommand(ProjectDocument *document, std::optional<ForcedChoiceStudy> before,
                    std::optional<ForcedChoiceStudy> after, const QString &text, int mergeKey = -1);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeKey >= 0 ? kId : -1; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    ProjectDocument *m_document;
    std::optional<ForcedChoiceStudy> m_before;
    std::optional<ForcedChoiceStudy> m_after;
    int m_mergeKey;
};

} // namespace lipsync::studio
