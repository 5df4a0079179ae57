#include "preview/SpeechDialog.h"

#include "context/ModelKinds.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace lipsync::studio {

SpeechDialog::SpeechDialog(const QStringList &kinds, double frameRate, QWidget *parent)
    : QDialog(parent), m_media(new QLineEdit(this)), m_transcript(new QPlainTextEdit(this)),
      m_frameRate(new QDoubleSpinBox(this)), m_model(new QComboBox(this)), m_note(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Generate from Speech"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("Faces for any recording with a transcript: the speech is aligned to its "
                                "words, labelled per frame and given to a trained dynamic model."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *form = new QFormLayout;
    auto *fileRow = new QHBoxLayout;
    m_media->setPlaceholderText(tr("An audio or video file"));
    auto *browseButton = new QPushButton(tr("Browse…"), this);
    fileRow->addWidget(m_media, 1);
    fileRow->addWidget(browseButton);
    form->addRow(tr("Speech:"), fileRow);
    m_transcript->setPlaceholderText(tr("The words spoken, e.g. \"bin blue at f two now\""));
    m_transcript->setTabChangesFocus(true);
    m_transcript->setMaximumHeight(m_transcript->fontMetrics().height() * 5);
    form->addRow(tr("Transcript:"), m_transcript);
    m_frameRate->setRange(1.0, 120.0);
    m_frameRate->setDecimals(3);
    m_frameRate->setSuffix(tr(" fps"));
    m_frameRate->setValue(frameRate > 0 ? frameRate : 25.0);
    form->addRow(tr("Frame rate:"), m_frameRate);
    for (const QString &kind : kinds)
        m_model->addItem(ModelKinds::name(kind), kind);
    form->addRow(tr("Model:"), m_model);
    layout->addLayout(form);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Generate"));
    layout->addWidget(m_buttons);

    connect(browseButton, &QPushButton::clicked, this, &SpeechDialog::browse);
    connect(m_media, &QLineEdit::editingFinished, this, [this] { setMediaPath(m_media->text()); });
    connect(m_media, &QLineEdit::textChanged, this, &SpeechDialog::updateState);
    connect(m_transcript, &QPlainTextEdit::textChanged, this, &SpeechDialog::updateState);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    updateState();
}

QString SpeechDialog::mediaPath() const
{
    return m_media->text().trimmed();
}

QString SpeechDialog::transcript() const
{
    return m_transcript->toPlainText().simplified();
}

double SpeechDialog::frameRate() const
{
    return m_frameRate->value();
}

QString SpeechDialog::kind() const
{
    return m_model->currentData().toString();
}

void SpeechDialog::setMediaPath(const QString &path)
{
    if (m_media->text() != path)
        m_media->setText(path);
    const QFileInfo info(path);
    if (!info.isFile())
        return;
    // A transcript beside the file (same stem), in the order the CLI prefers them.
    if (!transcript().isEmpty() && transcript() != m_autoTranscript)
        return; // typed by the user: keep it
    for (const std::string &ext : transcriptExtensions()) {
        const QString candidate = info.dir().filePath(info.completeBaseName() + QString::fromStdString(ext));
        if (!QFileInfo::exists(candidate))
            continue;
        try {
            m_autoTranscript = QString::fromStdString(readTranscript(candidate.toStdString()).text());
            m_transcript->setPlainText(m_autoTranscript);
            return;
        } catch (const Error &) {
            // unreadable: the user types the words
        }
    }
}

void SpeechDialog::browse()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Choose Speech"), QFileInfo(mediaPath()).absolutePath(),
        tr("Audio and video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;All files (*)"));
    if (!path.isEmpty())
        setMediaPath(path);
}

void SpeechDialog::updateState()
{
    QString problem;
    if (m_model->count() == 0)
        problem = tr("Train a dynamic model in the Models panel first.");
    else if (mediaPath().isEmpty() || !QFileInfo(mediaPath()).isFile())
        problem = tr("Choose an audio or video file.");
    else if (transcript().isEmpty())
        problem = tr("Type the words spoken (no transcript file was found beside it).");
    m_note->setText(problem);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace lipsync::studio
