#pragma once
// Help ▸ Keyboard Shortcuts: every action of a window that has a key, read from the actions
// themselves (so the list cannot drift from the keys that work), grouped by the menu that holds
// each one, else by the panel it belongs to.
#include <QDialog>
#include <QList>
#include <QString>

namespace lipsync::studio {

struct ShortcutRow
{
    QString group; // "File", "Timeline", ...
    QString action;
    QString keys; // native text, "Ctrl+S, Ctrl+Shift+S"
};

class ShortcutsDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ShortcutsDialog(QWidget *window);

    // The rows of `window`'s actions with shortcuts, menus first (in menu-bar order), each
    // action once.
    static QList<ShortcutRow> rows(QWidget *window);
};

} // namespace lipsync::studio
