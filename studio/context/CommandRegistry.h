#pragma once
// The studio's commands by name (StudioCommand), each with the one QAction that menus, toolbars
// and shortcuts share; the context owns it (StudioContext::commands()), every panel and menu adds
// its commands to it. The actions' enabled state is their command's validate() on the context,
// re-read whenever the context or its document changes (revalidate(); as the frame moves, only
// the commands that follow it), so no panel computes a command's state itself. The keys work
// window-wide once setShortcutWidget() names the window.
#include "context/StudioCommand.h"

#include <QObject>
#include <QPointer>

#include <map>

class QAction;
class QWidget;

namespace lipsync::studio {

class CommandRegistry : public QObject
{
    Q_OBJECT
public:
    explicit CommandRegistry(StudioContext *context);

    // Registers `command` (its name unique) and returns its action. `owner`, when given, is the
    // object the command's functions use: the command and its action go when it does.
    QAction *add(StudioCommand command, QObject *owner = nullptr);
    // Registers a panel's own `action` (its keys, scope and triggers stay as the panel made them)
    // as the command `name`: it is enabled when `validate` says so, as every command is.
    void adopt(const QString &name, QAction *action, std::function<bool(const StudioContext &)> validate,
               QObject *owner);
    // The action of the command called `name` (null: none).
    QAction *action(const QString &name) const;
    // Runs the command called `name` if it validates; false if it does not, or there is none.
    bool run(const QString &name);
    // Every action enabled as its command's validate() says.
    void revalidate();
    // The window whose shortcuts the commands' keys are (those added before and after).
    void setShortcutWidget(QWidget *widget);

private:
    struct Entry
    {
        StudioCommand command;
        QAction *action;
        bool adopted = false; // the action is a panel's: it runs what the panel connected
    };
    void forgetWith(QObject *owner, const QString &name);
    // Every command's action enabled as it validates; `frameOnly`: those that follow the frame.
    void validate(bool frameOnly);
    // Cleared as the context dies: its undo stack, deleted after it, still signals (cleanChanged).
    QPointer<StudioContext> m_context;
    QPointer<QWidget> m_shortcutWidget;
    std::map<QString, Entry> m_commands;
};

} // namespace lipsync::studio
