#pragma once
// The Models dock: the AAMs and dynamic models the project refers to, and the actions that
// build them (enabled by the faces and dynamics features).
#include <QWidget>

class QPushButton;
class QTreeWidget;

namespace lipsync {
class Project;
}

namespace lipsync::studio {

class ModelsPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ModelsPanel(QWidget *parent = nullptr);

    void setProject(const Project &project);
    QTreeWidget *list() const { return m_list; }
    QPushButton *buildAamButton() const { return m_buildAam; }
    QPushButton *trainButton() const { return m_train; }

private:
    QTreeWidget *m_list;
    QPushButton *m_buildAam;
    QPushButton *m_train;
};

} // namespace lipsync::studio
