#include "build/ModesView.h"

#include "aam/AamSynthesizer.h"
#include "aam/LandmarkScheme.h"

#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace lipsync::studio {

namespace {
constexpr int kCanvas = 280;
}

ModesView::ModesView(QWidget *parent)
    : QDialog(parent), m_picture(new QLabel(this)), m_summary(new QLabel(this))
{
    setObjectName(QStringLiteral("modesView"));
    setWindowTitle(tr("AAM Modes of Variation"));
    auto *layout = new QVBoxLayout(this);
    m_picture->setFixedSize(kCanvas, kCanvas);
    m_picture->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_picture, 0, Qt::AlignHCenter);
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    auto *grid = new QGridLayout;
    for (int i = 0; i < kModes; ++i) {
        auto *slider = new QSlider(Qt::Horizontal, this);
        slider->setRange(-kSteps, kSteps);
        slider->setValue(0);
        slider->setToolTip(tr("Combined mode %1, -3 to +3 standard deviations").arg(i + 1));
        auto *value = new QLabel(this);
        value->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("+3.0 s.d.")));
        grid->addWidget(new QLabel(tr("Mode %1").arg(i + 1), this), i, 0);
        grid->addWidget(slider, i, 1);
        grid->addWidget(value, i, 2);
        m_sliders << slider;
        m_values << value;
        connect(slider, &QSlider::valueChanged, this, &ModesView::render);
    }
    layout->addLayout(grid);
    auto *reset = new QPushButton(tr("&Reset to Mean"), this);
    connect(reset, &QPushButton::clicked, this, &ModesView::resetModes);
    layout->addWidget(reset, 0, Qt::AlignRight);
    render();
}

ModesView::~ModesView() = default;

void ModesView::setModel(std::shared_ptr<const AamModel> model)
{
    m_synth.reset();
    m_model = std::move(model);
    if (m_model)
        m_synth = std::make_unique<AamSynthesizer>(*m_model);
    render();
}

void ModesView::setMode(int mode, double sd)
{
    if (mode >= 0 && mode < m_sliders.size())
        m_sliders[mode]->setValue(int(std::lround(std::clamp(sd, -3.0, 3.0) / 3.0 * kSteps)));
}

double ModesView::mode(int mode) const
{
    return mode >= 0 && mode < m_sliders.size() ? 3.0 * m_sliders[mode]->value() / kSteps : 0.0;
}

void ModesView::resetModes()
{
    for (QSlider *s : m_sliders) {
        const QSignalBlocker block(s);
        s->setValue(0);
    }
    render();
}

void ModesView::render()
{
    const int available = m_model ? std::min(kModes, m_model->combinedModes()) : 0;
    for (int i = 0; i < kModes; ++i) {
        m_sliders[i]->setEnabled(i < available);
        m_values[i]->setText(i < available ? tr("%1 s.d.").arg(mode(i), 0, 'f', 1) : QString());
    }
    if (!m_model || !m_synth) {
        m_face = {};
        m_picture->setText(tr("No AAM yet: label frames and choose Faces ▸ Build AAM."));
        m_summary->clear();
        return;
    }
    m_summary->setText(tr("%1 training frames, %2 shape, %3 texture and %4 combined modes.")
                           .arg(m_model->trainingImages)
                           .arg(m_model->shapeModes())
                           .arg(m_model->textureModes())
                           .arg(m_model->combinedModes()));
    Eigen::VectorXd c = Eigen::VectorXd::Zero(m_model->combinedModes());
    for (int i = 0; i < available; ++i)
        c[i] = mode(i) * std::sqrt(std::max(0.0, m_model->combinedVariances[i]));

    // Place the mean shape's bounding box in the middle of the canvas.
    const Eigen::VectorXd &mean = m_model->meanShape;
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    for (Eigen::Index k = 0; k + 1 < mean.size(); k += 2) {
        minX = std::min(minX, mean[k]);
        maxX = std::max(maxX, mean[k]);
        minY = std::min(minY, mean[k + 1]);
        maxY = std::max(maxY, mean[k + 1]);
    }
    const double extent = std::max({maxX - minX, maxY - minY, 1e-6});
    Similarity pose;
    pose.a = 0.62 * kCanvas / extent;
    pose.tx = kCanvas / 2.0 - pose.a * (minX + maxX) / 2.0;
    pose.ty = kCanvas / 2.0 - pose.a * (minY + maxY) / 2.0;

    cv::Mat canvas(kCanvas, kCanvas, CV_8UC3, cv::Scalar(43, 40, 38));
    m_synth->composite(c, pose, canvas);
    QImage image(canvas.data, canvas.cols, canvas.rows, int(canvas.step), QImage::Format_BGR888);
    m_face = image.copy();

    QPainter p(&m_face);
    p.setRenderHint(QPainter::Antialiasing);
    const Eigen::VectorXd shape = pose.apply(m_synth->shape(c));
    p.setPen(QPen(QColor(255, 255, 255, 110), 1.0));
    for (const auto &[a, b] : landmarkConnections())
        if (2 * std::max(a, b) + 1 < shape.size())
            p.drawLine(QPointF(shape[2 * a], shape[2 * a + 1]), QPointF(shape[2 * b], shape[2 * b + 1]));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 229, 255));
    for (Eigen::Index k = 0; k + 1 < shape.size(); k += 2)
        p.drawEllipse(QPointF(shape[k], shape[k + 1]), 2.0, 2.0);
    p.end();
    m_picture->setPixmap(QPixmap::fromImage(m_face));
}

} // namespace lipsync::studio
