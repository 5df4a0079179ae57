#include "document/SetTranscriptCommand.h"

#include "document/ProjectDocument.h"

#include <QCoreApplication>

namespace lipsync::studio {

namespace {

QString commandText(SetTranscriptCommand::Kind kind)
{
    switch (kind) {
    case SetTranscriptCommand::Kind::Propose:
        return QCoreApplication::translate("SetTranscriptCommand", "Propose transcript of %1");
    case SetTranscriptCommand::Kind::Accept:
        return QCoreApplication::translate("SetTranscriptCommand", "Accept transcript of %1");
    case SetTranscriptCommand::Kind::Edit: break;
    }
    return QCoreApplication::translate("SetTranscriptCommand", "Edit transcript of %1");
}

} // namespace

SetTranscriptCommand::SetTranscriptCommand(ProjectDocument *document, int row, TranscriptState before,
                                           TranscriptState after, Kind kind)
    : m_document(document), m_row(row), m_before(std::move(before)), m_after(std::move(after))
{
    setText(commandText(kind).arg(QString::fromStdString(document->sequence(row).id)));
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
