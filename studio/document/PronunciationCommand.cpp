#include "document/PronunciationCommand.h"

#include "document/ProjectDocument.h"

namespace lipsync::studio {

SetPronunciationsCommand::SetPronunciationsCommand(ProjectDocument *document, std::map<std::string, std::string> before,
                                                   std::map<std::string, std::string> after, const QString &text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void SetPronunciationsCommand::undo()
{
    m_document->applyPronunciations(m_before);
}

void SetPronunciationsCommand::redo()
{
    m_document->applyPronunciations(m_after);
}

} // namespace lipsync::studio
