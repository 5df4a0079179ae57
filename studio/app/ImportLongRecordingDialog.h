#pragma once
// File ▸ Import Long Recording: choose the recording (a video or sound file of one speaker,
// minutes to hours long) and the transcript of what is said in it (.txt, .srt, .vtt, .lab, .align
// or a TextGrid; a transcript beside the recording with its name is filled in), and where it is
// cut into utterances (UtteranceSplitOptions: the pause that ends one, its shortest and longest
// length, as `lipsync project import-long` takes them). Import is enabled once both files exist.
#include "project/UtteranceSplit.h"

#include <QDialog>

class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace lipsync::studio {

class ImportLongRecordingDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ImportLongRecordingDialog(QWidget *parent = nullptr);

    QLineEdit *recordingEdit() const { return m_recording; }
    QLineEdit *transcriptEdit() const { return m_transcript; }
    QDoubleSpinBox *pauseSpin() const { return m_pause; }
    QDoubleSpinBox *shortestSpin() const { return m_shortest; }
    QDoubleSpinBox *longestSpin() const { return m_longest; }
    QDialogButtonBox *buttons() const { return m_buttons; }

    QString recordingPath() const;
    QString transcriptPath() const;
    UtteranceSplitOptions splitOptions() const;
    // Picks `path` and, while no transcript is chosen, the transcript beside it, if any.
    void setRecordingPath(const QString &path);

private:
    void browseRecording();
    void browseTranscript();
    void updateState();

    QLineEdit *m_recording;
    QLineEdit *m_transcript;
    QDoubleSpinBox *m_pause;
    QDoubleSpinBox *m_shortest;
    QDoubleSpinBox *m_longest;
    QLabel *m_note;
    QDialogButtonBox *m_buttons;
};

} // namespace lipsync::studio
