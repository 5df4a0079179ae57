#pragma once
// One user command of the studio, as Aegisub's cmd::Command: what it is called, its keys, whether
// it can run on the context as it is (validate) and what it does to the context (run). Menus,
// toolbars and shortcuts show it through the QAction CommandRegistry makes for it; the action is
// enabled exactly when validate() says so.
#include <QKeySequence>
#include <QList>
#include <QString>
#include <QStyle>

#include <functional>

namespace lipsync::studio {

class StudioContext;

struct StudioCommand
{
    QString name;                 // "frame/next": the registry's key and the action's objectName
    QString text;                 // translated, with its & mnemonic
    QList<QKeySequence> keys;     // the first is shown in the tooltip
    QStyle::StandardPixmap icon = QStyle::SP_CustomBase; // SP_CustomBase: none
    std::function<bool(const StudioContext &)> validate; // null: always possible
    std::function<void(StudioContext &)> run;
    // validate() reads the current frame: re-read as the frame moves (the others are not, so that
    // playback does not validate every command 30 times a second).
    bool followsFrame = false;
};

} // namespace lipsync::studio
