#include "context/WritableProject.h"

#include "context/ErrorReporter.h"
#include "document/ProjectDocument.h"

#include <QMessageBox>

namespace lipsync::studio {

bool ensureWritableProject(QWidget *parent, const ProjectDocument &document,
                           const std::function<bool()> &saveProject, const QString &title, const QString &question)
{
    if (!document.isOpen() || !document.isReadOnly())
        return true;
    if (!ErrorReporter::isBatchMode() && QMessageBox::question(parent, title, question) != QMessageBox::Yes)
        return false;
    return saveProject && saveProject() && !document.isReadOnly();
}

} // namespace lipsync::studio
