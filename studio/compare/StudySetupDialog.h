#pragma once
// Sets up the blind study (paper §4): which methods to compare (the recorded video "real" and
// the project's trained models), how many utterances to draw from the project (sequences with
// features and phones), how often every ordered pair is shown, and the seed of the random
// order. The design itself (every pair twice with sides swapped, random order per participant)
// is ForcedChoiceStudy's.
#include "project/ForcedChoiceStudy.h"

#include <QDialog>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace lipsync {
class Project;
}

namespace lipsync::studio {

class StudySetupDialog : public QDialog
{
    Q_OBJECT
public:
    StudySetupDialog(const Project &project, QWidget *parent = nullptr);

    QListWidget *methodList() const { return m_methods; }
    QSpinBox *utteranceCount() const { return m_utterances; }
    QSpinBox *repeatCount() const { return m_repeats; }
    QSpinBox *seed() const { return m_seed; }
    QCheckBox *holdOutCheck() const { return m_holdOut; }
    // The design for the current choices, or nullopt (with the reason) when it is not valid.
    std::optional<ForcedChoiceStudy> study(QString *problem = nullptr) const;

private:
    void updateSummary();

    std::vector<std::string> m_pool;
    QListWidget *m_methods;
    QSpinBox *m_utterances;
    QSpinBox *m_repeats;
    QSpinBox *m_seed;
    QCheckBox *m_holdOut;
    QLabel *m_summary;
    QPushButton *m_ok = nullptr;
};

} // namespace lipsync::studio
