#include "context/ModelKinds.h"

namespace lipsync::studio {

const QStringList &ModelKinds::ids()
{
    static const QStringList list{QString::fromLatin1(modelKindId(ModelKind::Brand)),
                                  QString::fromLatin1(modelKindId(ModelKind::Dpds)),
                                  QString::fromLatin1(modelKindId(ModelKind::Slds)),
                                  QString::fromLatin1(modelKindId(ModelKind::HmmMean))};
    return list;
}

bool ModelKinds::contains(const QString &id)
{
    return isDynamicModelKind(id.toStdString());
}

QString ModelKinds::name(ModelKind kind)
{
    switch (kind) {
    case ModelKind::Dpds:
        return tr("DPDS");
    case ModelKind::Slds:
        return tr("SLDS");
    case ModelKind::Brand:
        return tr("Brand");
    case ModelKind::HmmMean:
        return tr("HMM-mean");
    }
    return {};
}

QString ModelKinds::name(const QString &id)
{
    const std::optional<ModelKind> kind = parseModelKind(id.toStdString());
    return kind ? name(*kind) : id;
}

QString ModelKinds::name(const std::string &id)
{
    return name(QString::fromStdString(id));
}

QString ModelKinds::description(const QString &id)
{
    switch (parseModelKind(id.toStdString()).value_or(ModelKind(-1))) {
    case ModelKind::Dpds:
        return tr("Deterministic-process dynamical system (the paper's model)");
    case ModelKind::Slds:
        return tr("Switching linear dynamical system");
    case ModelKind::Brand:
        return tr("Brand's Voice Puppetry: per-phone Gaussians over position and velocity");
    case ModelKind::HmmMean:
        return tr("Phoneme-mean baseline: one Gaussian per phone, frames independent");
    }
    return {};
}

QColor ModelKinds::colour(const QString &id)
{
    switch (parseModelKind(id.toStdString()).value_or(ModelKind(-1))) {
    case ModelKind::Dpds:
        return QColor(0xe5, 0x39, 0x35);
    case ModelKind::Slds:
        return QColor(0x43, 0xa0, 0x47);
    case ModelKind::Brand:
        return QColor(0xfb, 0x8c, 0x00);
    case ModelKind::HmmMean:
        return QColor(0x8e, 0x24, 0xaa);
    }
    return QColor(0x54, 0x6e, 0x7a);
}

QColor ModelKinds::colour(const std::string &id)
{
    return colour(QString::fromStdString(id));
}

} // namespace lipsync::studio
