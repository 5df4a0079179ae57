#include "app/ImportLongRecordingDialog.h"

#include "io/Transcript.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace lipsync::studio {

ImportLongRecordingDialog::ImportLongRecordingDialog(QWidget *parent)
    : QDialog(parent), m_recording(new QLineEdit(this)), m_transcript(new QLineEdit(this)),
      m_pause(new QDoubleSpinBox(this)), m_shortest(new QDoubleSpinBox(this)), m_longest(new QDoubleSpinBox(this)),
      m_note(new QLabel(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Import Long Recording"));
    setMinimumWidth(640);
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("A long recording of one speaker is aligned to its transcript and cut at its pauses "
                                "into utterances. Each becomes a sequence of the project with its words and "
                                "alignment; its clip is written into the project's clips folder."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *form = new QFormLayout;
    // A path with its Browse button; the label's mnemonic reaches the path.
    auto addFileRow = [this, form](const QString &label, QLineEdit *edit, const QString &placeholder) {
        edit->setPlaceholderText(placeholder);
        edit->setClearButtonEnabled(true);
        auto *row = new QHBoxLayout;
        auto *browse = new QPushButton(tr("Browse…"), this);
        row->addWidget(edit, 1);
        row->addWidget(browse);
        auto *name = new QLabel(label, this);
        name->setBuddy(edit);
        form->addRow(name, row);
        return browse;
    };
    QPushButton *recordingButton = addFileRow(tr("&Recording:"), m_recording, tr("A video or sound file"));
    QPushButton *transcriptButton = addFileRow(tr("&Transcript:"), m_transcript,
                                               tr("The words spoken: .txt, .srt, .vtt, .lab, .align or .TextGrid"));
    const UtteranceSplitOptions defaults;
    auto seconds = [](QDoubleSpinBox *spin, double value, double minimum, double maximum, const QString &tip) {
        spin->setRange(minimum, maximum);
        spin->setDecimals(2);
        spin->setSingleStep(0.1);
        spin->setSuffix(tr(" s"));
        spin->setValue(value);
        spin->setToolTip(tip);
    };
    seconds(m_pause, defaults.minimumPause, 0.05, 5.0,
            tr("A silence this long ends an utterance once it is long enough"));
    seconds(m_shortest, defaults.shortest, 0.1, 60.0, tr("How long an utterance lasts before a pause ends it"));
    seconds(m_longest, defaults.longest, 0.1, 600.0,
            tr("Beyond this, the longest silence so far (or else a word boundary) ends an utterance"));
    form->addRow(tr("&Pause that ends an utterance:"), m_pause);
    form->addRow(tr("&Shortest utterance:"), m_shortest);
    form->addRow(tr("L&ongest utterance:"), m_longest);
    layout->addLayout(form);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
    layout->addStretch(1);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    layout->addWidget(m_buttons);

    connect(recordingButton, &QPushButton::clicked, this, &ImportLongRecordingDialog::browseRecording);
    connect(transcriptButton, &QPushButton::clicked, this, &ImportLongRecordingDialog::browseTranscript);
    connect(m_recording, &QLineEdit::editingFinished, this, [this] { setRecordingPath(recordingPath()); });
    connect(m_recording, &QLineEdit::textChanged, this, &ImportLongRecordingDialog::updateState);
    connect(m_transcript, &QLineEdit::textChanged, this, &ImportLongRecordingDialog::updateState);
    // The longest never below the shortest.
    connect(m_shortest, &QDoubleSpinBox::valueChanged, m_longest, &QDoubleSpinBox::setMinimum);
    m_longest->setMinimum(m_shortest->value());
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    updateState();
}

QString ImportLongRecordingDialog::recordingPath() const
{
    return m_recording->text().trimmed();
}

QString ImportLongRecordingDialog::transcriptPath() const
{
    return m_transcript->text().trimmed();
}

UtteranceSplitOptions ImportLongRecordingDialog::splitOptions() const
{
    UtteranceSplitOptions options;
    options.minimumPause = m_pause->value();
    options.shortest = m_shortest->value();
    options.longest = m_longest->value();
    return options;
}

void ImportLongRecordingDialog::setRecordingPath(const QString &path)
{
    if (m_recording->text() != path)
        m_recording->setText(path);
    const QFileInfo info(path);
    if (!info.isFile() || !transcriptPath().isEmpty())
        return;
    // The extensions readTranscript() understands, in its order of preference; the folder's
    // entries are matched without regard to case (".TextGrid").
    const QDir folder = info.dir();
    for (const std::string &ext : transcriptExtensions()) {
        const QStringList found =
            folder.entryList({info.completeBaseName() + QString::fromStdString(ext)}, QDir::Files);
        if (!found.isEmpty()) {
            m_transcript->setText(folder.filePath(found.front()));
            return;
        }
    }
}

void ImportLongRecordingDialog::browseRecording()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Choose the Recording"), QFileInfo(recordingPath()).absolutePath(),
        tr("Video and sound (*.mp4 *.mov *.mkv *.avi *.webm *.mpg *.wav *.flac *.mp3 *.ogg *.m4a);;All files (*)"));
    if (!path.isEmpty())
        setRecordingPath(path);
}

void ImportLongRecordingDialog::browseTranscript()
{
    const QString start = transcriptPath().isEmpty() ? recordingPath() : transcriptPath();
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Choose the Transcript"), QFileInfo(start).absolutePath(),
        tr("Transcripts (*.txt *.srt *.vtt *.lab *.align *.TextGrid);;All files (*)"));
    if (!path.isEmpty())
        m_transcript->setText(path);
}

void ImportLongRecordingDialog::updateState()
{
    QString problem;
    if (!QFileInfo(recordingPath()).isFile())
        problem = tr("Choose the recording: a video or sound file.");
    else if (!QFileInfo(transcriptPath()).isFile())
        problem = tr("Choose the transcript of the recording.");
    m_note->setText(problem);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

} // namespace lipsync::studio
