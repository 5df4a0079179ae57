#include "app/ShortcutsDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSet>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace lipsync::studio {

namespace {

QString plain(QString text)
{
    return text.remove(QLatin1Char('&')).remove(QStringLiteral("…")).remove(QStringLiteral("...")).trimmed();
}

QString keysOf(const QAction *a)
{
    QStringList keys;
    for (const QKeySequence &k : a->shortcuts())
        if (!k.isEmpty())
            keys << k.toString(QKeySequence::NativeText);
    return keys.join(QStringLiteral(", "));
}

void collectMenu(const QMenu *menu, const QString &group, QSet<const QAction *> &seen, QList<ShortcutRow> &out)
{
    for (QAction *a : menu->actions()) {
        if (a->menu()) {
            collectMenu(a->menu(), group, seen, out);
            continue;
        }
        if (a->isSeparator() || seen.contains(a) || keysOf(a).isEmpty())
            continue;
        seen.insert(a);
        out.append({group, plain(a->text()), keysOf(a)});
    }
}

// The title of the dock (or else the window) an action's owner sits in.
QString panelOf(const QAction *a, const QWidget *window)
{
    for (const QObject *o = a->parent(); o; o = o->parent())
        if (const auto *dock = qobject_cast<const QDockWidget *>(o))
            return plain(dock->windowTitle());
    return plain(window->windowTitle().section(QStringLiteral(" — "), -1));
}

} // namespace

QList<ShortcutRow> ShortcutsDialog::rows(QWidget *window)
{
    QList<ShortcutRow> out;
    QSet<const QAction *> seen;
    if (auto *main = qobject_cast<QMainWindow *>(window))
        for (QAction *top : main->menuBar()->actions())
            if (top->menu())
                collectMenu(top->menu(), plain(top->text()), seen, out);
    // Then the panels' own actions (the timeline's S, M, ...), grouped by panel.
    QList<ShortcutRow> panels;
    for (QAction *a : window->findChildren<QAction *>()) {
        if (seen.contains(a) || a->isSeparator() || keysOf(a).isEmpty() || a->text().isEmpty())
            continue;
        seen.insert(a);
        panels.append({panelOf(a, window), plain(a->text()), keysOf(a)});
    }
    std::stable_sort(panels.begin(), panels.end(),
                     [](const ShortcutRow &x, const ShortcutRow &y) { return x.group < y.group; });
    return out + panels;
}

ShortcutsDialog::ShortcutsDialog(QWidget *window) : QDialog(window)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    auto *tree = new QTreeWidget(this);
    tree->setHeaderLabels({tr("Action"), tr("Keys")});
    tree->setRootIsDecorated(false);
    QTreeWidgetItem *group = nullptr;
    for (const ShortcutRow &row : rows(window)) {
        if (!group || group->text(0) != row.group) {
            group = new QTreeWidgetItem(tree, {row.group});
            QFont bold = group->font(0);
            bold.setBold(true);
            group->setFont(0, bold);
            group->setFirstColumnSpanned(true);
        }
        new QTreeWidgetItem(group, {row.action, row.keys});
    }
    tree->expandAll();
    tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(tree);
    layout->addWidget(buttons);
    resize(520, 600);
}

} // namespace lipsync::studio
