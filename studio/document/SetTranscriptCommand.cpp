#include "document/SetTranscriptCommand.h"

#include "document/ProjectDocument.h"

#include <QCoreApplication>

namespace lipsync::studio {

SetTranscriptCommand::SetTranscriptCommand(ProjectDocument *document, int row, QString before, QString after)
    : m_document(document), m_row(row), m_before(std::move(before)), m_after(std::move(after))
{
    setText(QCoreApplication::translate("SetTranscriptCommand", "Edit transcript of %1")
                .arg(QString::fromStdString(document->sequence(row).id)));
}

void SetTranscriptCommand::undo()
{
    m_document->applyTranscript(m_row, m_before);
}

void SetTranscriptCommand::redo()
{
    m_document->applyTranscript(m_row, m_after);
}

} // namespace lipsync::studio
