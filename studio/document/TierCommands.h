#pragma once
// Undoable change of one sequence's word and phone tiers (alignment and every timeline edit):
// stores the tiers before and after. Commands pushed with the same merge key (one boundary drag:
// the timeline pushes one per mouse move) merge into one undo step; a drag that ends where it
// started leaves no step at all.
#include "document/TierEdits.h"

#include <QUndoCommand>

namespace lipsync::studio {

class ProjectDocument;

class SetTiersCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x7431; // "t1"

    SetTiersCommand(ProjectDocument *document, int row, TierPair before, TierPair after, const QString &text,
                    int mergeKey = -1);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeKey >= 0 ? kId : -1; }
    bool mergeWith(const QUndoCommand *other) override;

    int row() const { return m_row; }
    const TierPair &before() const { return m_before; }
    const TierPair &after() const { return m_after; }

private:
    ProjectDocument *m_document;
    int m_row;
    TierPair m_before;
    TierPair m_after;
    int m_mergeKey;
};

} // namespace lipsync::studio
