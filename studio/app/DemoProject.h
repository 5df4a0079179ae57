#pragma once
// The bundled demo project (ten GRID clips). Looked up, in order, in
//   $LIPSYNC_DEMO_DIR                                  (an override for packagers and tests)
//   <executable dir>/../share/lipsync/demo             (installed: <prefix>/bin/lipsync-studio)
//   <LIPSYNC_SOURCE_DIR>/resources/demo                (a build tree; compile definition)
// A folder qualifies if it holds project.json or a media/ folder. Without project.json the
// project is built in memory from media/ (Project::fromMediaFolder).
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
