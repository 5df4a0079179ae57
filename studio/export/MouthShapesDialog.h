#pragma once
// File ▸ Export ▸ Mouth Shapes: the nine Rhubarb shapes the mouth cues are made of, as this
// person's mouth makes them (core/animation/MouthMapping). Each row shows the shape drawn by the
// AAM at the project frame nearest it, what taught it (the frames of its phones, or the user), and
// its four cue features (opening, width, rounding, teeth showing, 0..1 over this person's range).
// The user edits the numbers, takes them from the frame shown in the studio, or resets a shape
// to the learned one: every change is one undo step on the project (Project::mouthShapes), and
// the next cue export uses it. Learning measures every tracked, aligned frame of the project, in
// the background.
#include "animation/MouthMapping.h"
#include "animation/MouthTrack.h"

#include <QDialog>
#include <QPointer>

#include <array>
#include <memory>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QScrollArea;

namespace lipsync {
class AamModel;
class Task;
}

namespace lipsync::studio {

class StudioContext;

class MouthShapesDialog : public QDialog
{
    Q_OBJECT
public:
    MouthShapesDialog(StudioContext *context, QWidget *parent = nullptr);
    ~MouthShapesDialog() override;

    // Learns the mapping again from the project's frames (in the background); the task, or null
    // when there is no AAM (the status line says so).
    Task *relearn();
    // After learning: the mapping with the user's shapes applied.
    const MouthMapping *mapping() const { return m_learned ? &m_shown : nullptr; }

    // Row widgets, for tests: the spin box of `feature` (0 opening .. 3 teeth) of `shape`.
    QDoubleSpinBox *featureBox(MouthShape shape, int feature) const;
    QPushButton *fromFrameButton(MouthShape shape) const;
    QPushButton *resetButton(MouthShape shape) const;
    QLabel *statusLabel() const { return m_status; }

protected:
    void showEvent(QShowEvent *event) override;

private:
    struct Learned;
    struct Row
    {
        QLabel *picture = nullptr;
        QLabel *taught = nullptr;
        std::array<QDoubleSpinBox *, MouthMapping::kCueFeatures> features{};
        QPushButton *fromFrame = nullptr;
        QPushButton *reset = nullptr;
    };
    void refresh();
    void fitToRows();
    void setUsersShape(MouthShape shape, const MouthMapping::CueFeatures &features, const QString &text, int mergeKey);
    void takeFromCurrentFrame(MouthShape shape);
    QPixmap picture(MouthShape shape) const;

    StudioContext *m_context;
    QLabel *m_status;
    QScrollArea *m_scroll = nullptr;
    bool m_sized = false;
    std::array<Row, kMouthShapeCount> m_rows;
    std::shared_ptr<const Learned> m_learned;
    MouthMapping m_shown;
    QPointer<Task> m_task;
};

} // namespace lipsync::studio
