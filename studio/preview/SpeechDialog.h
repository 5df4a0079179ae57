#pragma once
// Generate from speech: choose a media file (any audio or video), its transcript (read from a
// transcript file beside it when there is one: .align, .lab, .txt, .TextGrid), the frame rate of
// the faces and the dynamic model to generate them with.
#include <QDialog>
#include <QStringList>

class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace lipsync::studio {

class SpeechDialog : public QDialog
{
    Q_OBJECT
public:
    // `kinds`: the trained dynamic models to choose from ("dpds", ...).
    SpeechDialog(const QStringList &kinds, double frameRate, QWidget *parent = nullptr);

    QLineEdit *mediaEdit() const { return m_media; }
    QPlainTextEdit *transcriptEdit() const { return m_transcript; }
    QDoubleSpinBox *frameRateSpin() const { return m_frameRate; }
    QComboBox *modelCombo() const { return m_model; }
    QDialogButtonBox *buttons() const { return m_buttons; }

    QString mediaPath() const;
    QString transcript() const;
    double frameRate() const;
    QString kind() const;

    // Picks `path` and reads the transcript beside it, if any.
    void setMediaPath(const QString &path);

private:
    void browse();
    void updateState();

    QLineEdit *m_media;
    QPlainTextEdit *m_transcript;
    QDoubleSpinBox *m_frameRate;
    QComboBox *m_model;
    QLabel *m_note;
    QDialogButtonBox *m_buttons;
    QString m_autoTranscript; // what was read from a file (replaced when another file is picked)
};

} // namespace lipsync::studio
