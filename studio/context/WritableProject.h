#pragma once
// Work that writes into the project's folder (the clips of an imported recording, a live
// session's sound) needs a folder of the user's own, and the bundled demo is read-only: the user
// is asked `question` (under `title`) whether to save the project elsewhere first, and
// `saveProject` (the app's Save, which asks for the folder) does it. In batch mode (tests) it
// saves without asking.
#include <QString>

#include <functional>

class QWidget;

namespace lipsync::studio {

class ProjectDocument;

// True when the project can be written into: it is not read-only, or was saved into a folder of
// the user's own.
bool ensureWritableProject(QWidget *parent, const ProjectDocument &document,
                           const std::function<bool()> &saveProject, const QString &title, const QString &question);

} // namespace lipsync::studio
