#include "export/MouthShapesDialog.h"

#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include "aam/AamModel.h"
#include "aam/AamSynthesizer.h"
#include "aam/Procrustes.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lipsync::studio {

// What learning hands to the GUI thread: the AAM, the project's measured frames and the mapping
// learned from them without the user's shapes.
struct MouthShapesDialog::Learned
{
    std::shared_ptr<const AamModel> aam;
    std::unique_ptr<MouthMeasurer> measurer;
    std::vector<MouthTrack> tracks;
    MouthMapping mapping;
};

namespace {

constexpr QSize kPictureSize(96, 60);

QString featureName(int feature)
{
    const std::array<const char *, 4> names{QT_TRANSLATE_NOOP("MouthShapesDialog", "Opening"),
                                            QT_TRANSLATE_NOOP("MouthShapesDialog", "Width"),
                                            QT_TRANSLATE_NOOP("MouthShapesDialog", "Rounding"),
                                            QT_TRANSLATE_NOOP("MouthShapesDialog", "Teeth")};
    return QCoreApplication::translate("MouthShapesDialog", names[size_t(feature)]);
}

QString shapeDescription(MouthShape shape)
{
    switch (shape) {
    case MouthShape::A: return MouthShapesDialog::tr("Closed, lips pressed: P, B, M");
    case MouthShape::B: return MouthShapesDialog::tr("Slightly open, teeth clenched: K, S, T, EE");
    case MouthShape::C: return MouthShapesDialog::tr("Open: EH as in men, AE as in bat");
    case MouthShape::D: return MouthShapesDialog::tr("Wide open: AA as in father");
    case MouthShape::E: return MouthShapesDialog::tr("Slightly rounded: AO as in off, ER as in bird");
    case MouthShape::F: return MouthShapesDialog::tr("Puckered: UW as in you, OW as in show, W");
    case MouthShape::G: return MouthShapesDialog::tr("Upper teeth on the lower lip: F, V");
    case MouthShape::H: return MouthShapesDialog::tr("Tongue raised behind the teeth: long L");
    case MouthShape::X: return MouthShapesDialog::tr("Rest, in every pause");
    }
    return {};
}

} // namespace

MouthShapesDialog::MouthShapesDialog(StudioContext *context, QWidget *parent)
    : QDialog(parent), m_context(context), m_status(new QLabel(this))
{
    setWindowTitle(tr("Mouth Shapes"));
    m_status->setWordWrap(true);
    auto *grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("<b>Shape</b>")), 0, 1);
    grid->addWidget(new QLabel(tr("<b>Taught by</b>")), 0, 2);
    for (int k = 0; k < MouthMapping::kCueFeatures; ++k)
        grid->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(featureName(k))), 0, 3 + k);
    for (int s = 0; s < kMouthShapeCount; ++s) {
        const MouthShape shape = MouthShape(s);
        const QString letter(QLatin1Char(mouthShapeLetter(shape)));
        Row &row = m_rows[size_t(s)];
        row.picture = new QLabel;
        row.picture->setFixedSize(kPictureSize);
        row.picture->setAlignment(Qt::AlignCenter);
        auto *name = new QLabel(QStringLiteral("<b>%1</b> %2").arg(letter, shapeDescription(shape).toHtmlEscaped()));
        name->setWordWrap(true);
        name->setMinimumWidth(200);
        row.taught = new QLabel;
        grid->addWidget(row.picture, s + 1, 0);
        grid->addWidget(name, s + 1, 1);
        grid->addWidget(row.taught, s + 1, 2);
        for (int k = 0; k < MouthMapping::kCueFeatures; ++k) {
            auto *box = new QDoubleSpinBox;
            box->setRange(0.0, 1.0);
            box->setSingleStep(0.05);
            box->setDecimals(2);
            box->setEnabled(false);
            box->setToolTip(tr("%1 of shape %2, from 0 to 1 over this person's range").arg(featureName(k), letter));
            // X is rest in silence, whatever the mouth: nothing to set.
            if (shape != MouthShape::X)
                connect(box, &QDoubleSpinBox::valueChanged, this, [this, shape, s] {
                    MouthMapping::CueFeatures f;
                    for (int j = 0; j < MouthMapping::kCueFeatures; ++j)
                        f[j] = m_rows[size_t(s)].features[size_t(j)]->value();
                    setUsersShape(shape, f, tr("Set Mouth Shape %1").arg(QLatin1Char(mouthShapeLetter(shape))), s);
                });
            row.features[size_t(k)] = box;
            grid->addWidget(box, s + 1, 3 + k);
        }
        row.fromFrame = new QPushButton(tr("From Frame"));
        row.fromFrame->setToolTip(tr("Make shape %1 the mouth of the frame shown in the studio").arg(letter));
        row.reset = new QPushButton(tr("Learned"));
        row.reset->setToolTip(tr("Use the shape learned from this person's frames again"));
        row.fromFrame->setEnabled(false);
        row.reset->setEnabled(false);
        if (shape != MouthShape::X) {
            connect(row.fromFrame, &QPushButton::clicked, this, [this, shape] { takeFromCurrentFrame(shape); });
            connect(row.reset, &QPushButton::clicked, this, [this, shape, letter] {
                auto shapes = m_context->document()->project().mouthShapes;
                shapes.erase(letter.toStdString());
                m_context->document()->requestMouthShapes(shapes, tr("Reset Mouth Shape %1").arg(letter));
            });
            grid->addWidget(row.fromFrame, s + 1, 7);
            grid->addWidget(row.reset, s + 1, 8);
        }
    }
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    auto *learnAgain = buttons->addButton(tr("Learn Again"), QDialogButtonBox::ActionRole);
    learnAgain->setToolTip(tr("Measure the project's tracked, aligned frames again"));
    connect(learnAgain, &QPushButton::clicked, this, &MouthShapesDialog::relearn);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // Scrolls on small screens (1280 x 800) instead of growing past them.
    auto *rows = new QWidget;
    rows->setLayout(grid);
    auto *scroll = new QScrollArea;
    scroll->setWidget(rows);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll = scroll;
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_status);
    layout->addWidget(scroll, 1);
    auto *note = new QLabel(tr("Silence is always X and /p b m/ always A; the other frames take the shape they look "
                               "most like, their phone's shape first. Shapes you set are kept with the project."));
    note->setWordWrap(true);
    layout->addWidget(note);
    layout->addWidget(buttons);
    ProjectDocument *document = m_context->document();
    connect(document, &ProjectDocument::mouthShapesChanged, this, &MouthShapesDialog::refresh);
    connect(document, &ProjectDocument::documentReset, this, [this] {
        m_learned.reset();
        if (isVisible())
            relearn();
        else
            refresh();
    });
}

void MouthShapesDialog::showEvent(QShowEvent *event)
{
    fitToRows();
    QDialog::showEvent(event);
}

void MouthShapesDialog::fitToRows()
{
    // The rows' full width (it grows as learning fills them in), and all nine rows where the
    // screen allows (a 1280 x 800 screen scrolls the last ones).
    QWidget *rows = m_scroll->widget();
    m_scroll->setMinimumWidth(std::max(rows->sizeHint().width(), rows->minimumSizeHint().width())
                              + m_scroll->verticalScrollBar()->sizeHint().width() + 4);
    const int height = m_sized ? this->height() : std::min(rows->sizeHint().height() + 150, 720);
    m_sized = true;
    resize(std::max(width(), sizeHint().width()), height);
}

MouthShapesDialog::~MouthShapesDialog()
{
    if (m_task)
        m_task->cancel();
}

Task *MouthShapesDialog::relearn()
{
    QString problem;
    const std::shared_ptr<const AamModel> aam = m_context->modelStore()->aam(&problem);
    if (!aam) {
        m_status->setText(problem.isEmpty() ? tr("The project has no AAM yet: build one in the Models panel, then "
                                                 "track and align its sequences.")
                                            : problem);
        return nullptr;
    }
    if (m_task)
        m_task->cancel();
    m_status->setText(tr("Learning this person's mouth shapes…"));
    Project project = m_context->document()->project();
    QPointer<MouthShapesDialog> self(this);
    m_task = m_context->taskRunner()->start(tr("Learn the mouth shapes"), [project = std::move(project), aam,
                                                                           self](Feedback &feedback) -> TaskRunner::Commit {
        auto learned = std::make_shared<Learned>();
        learned->aam = aam;
        learned->measurer = std::make_unique<MouthMeasurer>(*aam);
        learned->tracks = projectMouthTracks(*learned->measurer, project);
        feedback.throwIfCanceled();
        try {
            learned->mapping = MouthMapping::learn(learned->tracks);
        } catch (const Error &e) {
            const QString why = QString::fromUtf8(e.what());
            return [self, why] {
                if (self)
                    self->m_status->setText(tr("Not learned: %1. Track and align more of the project.").arg(why));
            };
        }
        return [self, learned] {
            if (!self)
                return;
            self->m_learned = learned;
            int frames = 0;
            for (const MouthTrack &t : learned->tracks)
                frames += t.frameCount();
            self->m_status->setText(tr("Learned from %n frames", nullptr, frames)
                                    + tr(" of %n tracked, aligned sequences.", nullptr, int(learned->tracks.size())));
            self->refresh();
        };
    });
    return m_task;
}

void MouthShapesDialog::refresh()
{
    const bool learned = m_learned != nullptr;
    if (learned) {
        m_shown = m_learned->mapping;
        m_shown.applyUserShapes(m_context->document()->project().mouthShapes);
    }
    for (int s = 0; s < kMouthShapeCount; ++s) {
        const MouthShape shape = MouthShape(s);
        Row &row = m_rows[size_t(s)];
        const bool editable = learned && shape != MouthShape::X;
        for (int k = 0; k < MouthMapping::kCueFeatures; ++k) {
            QDoubleSpinBox *box = row.features[size_t(k)];
            const QSignalBlocker block(box);
            box->setEnabled(editable);
            if (learned)
                box->setValue(m_shown.shape(shape)[k]);
        }
        row.fromFrame->setEnabled(editable);
        row.reset->setEnabled(editable && m_shown.isUsers(shape));
        if (!learned) {
            row.taught->clear();
            row.picture->clear();
            continue;
        }
        row.taught->setText(m_shown.isUsers(shape)            ? tr("you")
                            : m_shown.framesOf(shape) > 0     ? tr("%n frames", nullptr, m_shown.framesOf(shape))
                                                              : tr("a drawing (no frames)"));
        row.picture->setPixmap(picture(shape));
    }
    if (isVisible())
        fitToRows();
}

QPixmap MouthShapesDialog::picture(MouthShape shape) const
{
    const auto [track, frame] = nearestFrameOfShape(m_learned->tracks, m_shown, shape);
    if (track < 0)
        return {};
    const Eigen::VectorXd c = m_learned->tracks[size_t(track)].features.row(frame).transpose();
    // The face drawn by the AAM at a fixed size, cropped to its mouth.
    const int side = 360;
    cv::Mat canvas(side, side, CV_8UC3, cv::Scalar(64, 64, 64));
    Similarity pose;
    pose.a = side * 0.9;
    pose.tx = pose.ty = side / 2.0;
    CompositeOptions options;
    options.region = FaceRegion::Full;
    options.matchColour = false;
    m_learned->measurer->synthesizer().composite(c, pose, canvas, options);
    const Eigen::VectorXd points = pose.apply(m_learned->measurer->shape(c));
    cv::Rect2d box(points[16], points[17], 0, 0); // mouth_left, then the other mouth points
    for (int i = 8; i < 18; ++i)
        box |= cv::Rect2d(points[2 * i], points[2 * i + 1], 1, 1);
    const double w = box.width * 1.5, h = w * kPictureSize.height() / kPictureSize.width();
    const cv::Rect crop = cv::Rect(cv::Rect2d(box.x + box.width / 2 - w / 2, box.y + box.height / 2 - h / 2, w, h))
                          & cv::Rect(0, 0, side, side);
    if (crop.area() <= 0)
        return {};
    cv::Mat mouth;
    cv::resize(canvas(crop), mouth, cv::Size(kPictureSize.width(), kPictureSize.height()), 0, 0, cv::INTER_AREA);
    const QImage image(mouth.data, mouth.cols, mouth.rows, int(mouth.step), QImage::Format_BGR888);
    return QPixmap::fromImage(image.copy());
}

void MouthShapesDialog::setUsersShape(MouthShape shape, const MouthMapping::CueFeatures &features, const QString &text,
                                      int mergeKey)
{
    auto shapes = m_context->document()->project().mouthShapes;
    shapes[std::string(1, mouthShapeLetter(shape))] = {features[0], features[1], features[2], features[3]};
    m_context->document()->requestMouthShapes(shapes, text, mergeKey);
}

void MouthShapesDialog::takeFromCurrentFrame(MouthShape shape)
{
    const ProjectDocument *document = m_context->document();
    const int row = m_context->currentSequence(), frame = m_context->currentFrame();
    if (!m_learned || row < 0 || row >= document->sequenceCount() || frame < 0
        || frame >= document->sequence(row).features.rows()) {
        m_status->setText(tr("The frame shown has no face features: choose a tracked sequence's frame first."));
        return;
    }
    const Eigen::VectorXd c = document->sequence(row).features.row(frame).transpose();
    setUsersShape(shape, m_learned->mapping.cueFeatures(m_learned->measurer->measure(c)),
                  tr("Mouth Shape %1 from Frame %2").arg(QLatin1Char(mouthShapeLetter(shape))).arg(frame + 1), -1);
}

QDoubleSpinBox *MouthShapesDialog::featureBox(MouthShape shape, int feature) const
{
    return m_rows[size_t(shape)].features[size_t(feature)];
}

QPushButton *MouthShapesDialog::fromFrameButton(MouthShape shape) const
{
    return m_rows[size_t(shape)].fromFrame;
}

QPushButton *MouthShapesDialog::resetButton(MouthShape shape) const
{
    return m_rows[size_t(shape)].reset;
}

} // namespace lipsync::studio
