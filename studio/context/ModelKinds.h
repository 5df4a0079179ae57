#pragma once
// The dynamic model kinds as the studio shows them: one translated name and one colour per kind,
// used by every panel, plot legend, menu and dialog that names a model (the ids and the factory are
// core's, dynamics/ModelKind.h). Names are short enough for a chart legend at 9 pt.
#include "dynamics/ModelKind.h"

#include <QColor>
#include <QCoreApplication>
#include <QStringList>

#include <string>

namespace lipsync::studio {

class ModelKinds
{
    Q_DECLARE_TR_FUNCTIONS(ModelKinds)

public:
    // The ids in the studio's order, the default first: Brand, whose lips follow the recordings
    // best with phones in context and variance compensation (docs/performance.md, "Phones in
    // context"), then the paper's DPDS, SLDS and HMM-mean.
    static const QStringList &ids();
    static bool contains(const QString &id);

    // The user-visible name: "DPDS", "SLDS", "Brand", "HMM-mean" (translated); any other id is
    // returned as it is.
    static QString name(ModelKind kind);
    static QString name(const QString &id);
    static QString name(const std::string &id);
    // A one-line description for tool tips: what the model is.
    static QString description(const QString &id);
    // The kind's colour in plots and lists; grey for any other id.
    static QColor colour(const QString &id);
    static QColor colour(const std::string &id);
};

} // namespace lipsync::studio
