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
    connect(context, &StudioContext::currentFrameChanged, this, [this] { validate(true); });
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
    forgetWith(owner, name);
    return action;
}

void CommandRegistry::adopt(const QString &name, QAction *action, std::function<bool(const StudioContext &)> validate,
                            QObject *owner)
{
    if (m_commands.count(name))
        throw Error("command " + name.toStdString() + " registered twice");
    action->setObjectName(name);
    if (validate && m_context)
        action->setEnabled(validate(*m_context));
    StudioCommand command{name, action->text(), action->shortcuts(), QStyle::SP_CustomBase, std::move(validate), nullptr};
    m_commands.emplace(name, Entry{std::move(command), action, true});
    forgetWith(owner, name);
}

void CommandRegistry::forgetWith(QObject *owner, const QString &name)
{
    if (!owner)
        return;
    connect(owner, &QObject::destroyed, this, [this, name] {
        const auto it = m_commands.find(name);
        if (it == m_commands.end())
            return;
        if (!it->second.adopted) // an adopted action is its panel's, and goes with it
            delete it->second.action;
        m_commands.erase(it);
    });
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
    if (!m_context || (command.validate && !command.validate(*m_context)))
        return false;
    if (it->second.adopted) {
        it->second.action->setEnabled(true); // it validates: a stale state must not swallow the trigger
        it->second.action->trigger();
    }
    else if (command.run)
        command.run(*m_context);
    else
        return false;
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
    validate(false);
}

void CommandRegistry::validate(bool frameOnly)
{
    if (!m_context)
        return;
    for (auto &[name, entry] : m_commands)
        if (entry.command.validate && (entry.command.followsFrame || !frameOnly))
            entry.action->setEnabled(entry.command.validate(*m_context));
}

} // namespace lipsync::studio
