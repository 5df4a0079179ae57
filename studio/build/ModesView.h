#pragma once
// The modes of variation of an AAM: a slider per combined mode (the first six) from -3 to +3
// standard deviations, and the face the model synthesises for those parameters (AamSynthesizer:
// shape and texture together), with its 23 points drawn over it.
#include "aam/AamModel.h"

#include <QDialog>
#include <QImage>
#include <QVector>

#include <memory>

class QLabel;
class QSlider;

namespace lipsync {
class AamSynthesizer;
}

namespace lipsync::studio {

class ModesView : public QDialog
{
    Q_OBJECT
public:
    static constexpr int kModes = 6;
    static constexpr int kSteps = 30; // slider steps per 3 s.d.

    explicit ModesView(QWidget *parent = nullptr);
    ~ModesView() override;

    void setModel(std::shared_ptr<const AamModel> model);
    // Mode `mode` at `sd` standard deviations (-3..3).
    void setMode(int mode, double sd);
    double mode(int mode) const;
    void resetModes();
    // The face rendered now (null without a model).
    const QImage &face() const { return m_face; }
    QSlider *slider(int mode) const { return m_sliders.value(mode); }

private:
    void render();

    std::shared_ptr<const AamModel> m_model;
    std::unique_ptr<AamSynthesizer> m_synth;
    QVector<QSlider *> m_sliders;
    QVector<QLabel *> m_values;
    QLabel *m_picture;
    QLabel *m_summary;
    QImage m_face;
};

} // namespace lipsync::studio
