#pragma once
// The bundled demo project (ten GRID clips): demo/ among the shipped resources
// (util/ResourceLocator: $LIPSYNC_RESOURCE_DIR, else <executable dir>/../share/lipsync, which
// the build tree links to the sources' resources/). A folder qualifies if it holds project.json
// or a media/ folder. Without project.json the project is built in memory from media/
// (Project::fromMediaFolder).
#include "project/Project.h"

#include <QString>

namespace lipsync::studio {

class DemoProject
{
public:
    static QString locate();
    // Loads the demo in `folder`. Throws lipsync::Error.
    static Project load(const QString &folder);
    // Where "Save" of the read-only demo proposes to write it.
    static QString defaultSaveFolder();
};

} // namespace lipsync::studio
