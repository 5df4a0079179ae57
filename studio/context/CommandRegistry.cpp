#include "context/CommandRegistry.h"

#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "util/Error.h"

#include <QAction>
#include <QApplication>
#include <QStyle>
#include <QUndoStack>
#include <QWidget>

namespace lipsync::studio {

CommandRegistry::CommandRegistry(StudioContext *context)
    : QObject(context), m_context(context)
{
    // What a command's validity can depend on: the document, the sequence and frame worked on.
    ProjectDocument *document = context->document();
    connect(context, &StudioContext::sequenceRequested, this, &CommandRegistry::revalidate);
    connect(context, &StudioContext::sequenceLoadEnded, this, &CommandRegistry::revalidate);
    connect(context, &StudioContext::sequenceLoaded, this, &CommandRegistry::revalidate);
    connect(context, &StudioContext::currentFrameChanged, this, &CommandRegistry::revalidate);
    connect(context, &StudioContext::shownSpeechChanged, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::documentReset, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::sequencesAdded, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::sequencesRemoved, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::sequenceChanged, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::modelsChanged, this, &CommandRegistry::revalidate);
    connect(document, &ProjectDocument::locationChanged, this, &CommandRegistry::revalidate);
    connect(context->undoStack(), &QUndoStack::cleanChanged, this, &CommandRegistry::revalidate);
}

QAction *CommandRegistry::add(StudioCommand command, QObject *owner)
{
    if (m_commands.count(command.name))
        throw Error("command " + command.name.toStdString() + " registered twice");
    auto *action = new QAction(command.text, this);
    action->setObjectName(command.name);
    action->setShortcuts(command.keys);
    // Window-wide, so the keys work whichever dock has focus.
    action->setShortcutContext(Qt::WindowShortcut);
    if (command.icon != QStyle::SP_CustomBase)
        action->setIcon(QApplication::style()->standardIcon(command.icon));
    if (!command.keys.isEmpty())
        action->setToolTip(QStringLiteral("%1 (%2)").arg(QString(command.text).remove(QLatin1Char('&')).remove(QStringLiteral("…")),
                                                         command.keys.first().toString(QKeySequence::NativeText)));
    if (m_shortcutWidget)
        m_shortcutWidget->addAction(action);
    const QString name = command.name;
    connect(action, &QAction::triggered, this, [this, name] { run(name); });
    if (command.validate)
        action->setEnabled(command.validate(*m_context));
    m_commands.emplace(name, Entry{std::move(command), action});
    if (owner)
        connect(owner, &QObject::destroyed, this, [this, name] {
            const auto it = m_commands.find(name);
            if (it == m_commands.end())
                return;
            delete it->second.action;
            m_commands.erase(it);
        });
    return action;
}

QAction *CommandRegistry::action(const QString &name) const
{
    const auto it = m_commands.find(name);
    return it == m_commands.end() ? nullptr : it->second.action;
}

bool CommandRegistry::run(const QString &name)
{
    const auto it = m_commands.find(name);
    if (it == m_commands.end())
        return false;
    const StudioCommand &command = it->second.command;
    if (!m_context || (command.validate && !command.validate(*m_context)) || !command.run)
        return false;
    command.run(*m_context);
    return true;
}

void CommandRegistry::setShortcutWidget(QWidget *widget)
{
    m_shortcutWidget = widget;
    for (const auto &[name, entry] : m_commands)
        widget->addAction(entry.action);
}

void CommandRegistry::revalidate()
{
    if (!m_context)
        return;
    for (auto &[name, entry] : m_commands)
        if (entry.command.validate)
            entry.action->setEnabled(entry.command.validate(*m_context));
}

} // namespace lipsync::studio
