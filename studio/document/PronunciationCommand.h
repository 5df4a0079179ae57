#pragma once
// Undoable change of the project's pronunciation overrides (the Pronunciations dialog): stores
// the whole word -> phones map before and after (a project holds tens of overrides, not millions).
#include <QUndoCommand>

#include <map>
#include <string>

namespace lipsync::studio {

class ProjectDocument;

class SetPronunciationsCommand : public QUndoCommand
{
public:
    SetPronunciationsCommand(ProjectDocument *document, std::map<std::string, std::string> before,
                             std::map<std::string, std::string> after, const QString &text);

    void undo() override;
    void redo() override;

private:
    ProjectDocument *m_document;
    std::map<std::string, std::string> m_before;
    std::map<std::string, std::string> m_after;
};

} // namespace lipsync::studio
