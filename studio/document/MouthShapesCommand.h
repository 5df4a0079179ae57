#pragma once
// Undoable change of the user's own mouth shapes for cue export (Project::mouthShapes, edited in
// the Mouth Shapes dialog): the whole letter -> features map before and after. Edits of one
// spin box in a row (one mergeKey >= 0) merge into one undo step.
#include "project/Project.h"

#include <QUndoCommand>

#include <map>
#include <string>

namespace lipsync::studio {

class ProjectDocument;

class SetMouthShapesCommand : public QUndoCommand
{
public:
    using Shapes = std::map<std::string, Project::MouthShapeFeatures>;
    SetMouthShapesCommand(ProjectDocument *document, Shapes before, Shapes after, const QString &text, int mergeKey);

    void undo() override;
    void redo() override;
    int id() const override { return m_mergeKey >= 0 ? kId : -1; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    static constexpr int kId = 0x4d53; // "MS"
    ProjectDocument *m_document;
    Shapes m_before;
    Shapes m_after;
    int m_mergeKey;
};

} // namespace lipsync::studio
