#include "build/ModelsPanel.h"

#include "project/Project.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace lipsync::studio {

namespace {

QString kindText(const std::string &kind)
{
    if (kind == "aam") return ModelsPanel::tr("Appearance model");
    if (kind == "aligner") return ModelsPanel::tr("Phoneme aligner");
    if (kind == "dpds") return ModelsPanel::tr("DPDS");
    if (kind == "slds") return ModelsPanel::tr("SLDS");
    if (kind == "brand") return ModelsPanel::tr("Voice Puppetry");
    if (kind == "hmm") return ModelsPanel::tr("Phoneme-mean HMM");
    return QString::fromStdString(kind);
}

} // namespace

ModelsPanel::ModelsPanel(QWidget *parent)
    : QWidget(parent), m_list(new QTreeWidget(this)), m_buildAam(new QPushButton(tr("Build AAM…"), this)),
      m_train(new QPushButton(tr("Train…"), this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    m_list->setHeaderLabels({tr("Model"), tr("Kind"), tr("File")});
    m_list->setRootIsDecorated(false);
    m_list->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_list->header()->setStretchLastSection(false);
    layout->addWidget(m_list, 1);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_buildAam);
    buttons->addWidget(m_train);
    buttons->addStretch();
    layout->addLayout(buttons);
    m_buildAam->setEnabled(false);
    m_buildAam->setToolTip(tr("Building an Active Appearance Model comes with the faces feature "
                              "(landmark editor, AAM building and fitting)."));
    m_train->setEnabled(false);
    m_train->setToolTip(tr("Training dynamic models comes with the dynamics feature "
                           "(DPDS, SLDS, Voice Puppetry, phoneme means)."));
}

void ModelsPanel::setProject(const Project &project)
{
    m_list->clear();
    for (const ModelReference &m : project.models) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, QString::fromStdString(m.name));
        item->setText(1, kindText(m.kind));
        item->setText(2, QString::fromStdString(m.file));
        item->setToolTip(2, QString::fromStdString(project.resolve(m.file)));
    }
    if (project.models.empty()) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, tr("No models yet"));
        item->setFlags(Qt::NoItemFlags);
        item->setFirstColumnSpanned(true);
    }
}

} // namespace lipsync::studio
