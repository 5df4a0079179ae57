#pragma once
// The participant's screen of the blind study (paper §4): full-window, black, the two videos
// of a trial side by side playing together with the utterance's recorded sound, "Trial k of n",
// and nothing that names a method. Keys: Left / Right = that video is the real one, Down =
// can't decide, R or Space = replay, Esc = pause and ask whether to leave. An answer is taken
// once the trial's videos are on screen; the time from the start of playback to the answer is
// recorded with it.
#include "project/ForcedChoiceStudy.h"

#include <QElapsedTimer>
#include <QImage>
#include <QWidget>

#include <vector>

class QAudioOutput;
class QLabel;
class QMediaPlayer;
class QTimer;

namespace lipsync::studio {

struct StudyClip;

class ParticipantView : public QWidget
{
    Q_OBJECT
public:
    explicit ParticipantView(QWidget *parent = nullptr);
    ~ParticipantView() override;

    // Waiting for trial `index` (0-based) of `count` to be prepared.
    void showPreparing(int index, int count);
    // Trial `index` of `count`: both clips (same utterance, same length and sound) start playing.
    void showTrial(int index, int count, const StudyClip &left, const StudyClip &right);
    void showFinished();
    void showMessage(const QString &text);

    // Sound on/off (tests and screenshots run silent).
    void setAudioEnabled(bool enabled) { m_audioEnabled = enabled; }
    bool isAcceptingAnswers() const { return m_accepting; }
    bool isPlaying() const;
    int currentFrame() const { return m_frame; }
    QString progressText() const;
    QString promptText() const;

    // Esc asks before leaving; tests and the owner can skip the question.
    void setConfirmLeave(bool confirm) { m_confirmLeave = confirm; }

public slots:
    void replay();

signals:
    void answered(lipsync::StudyChoice choice, double seconds);
    void leaveRequested();

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    void tick();
    void stop();
    void answer(StudyChoice choice);
    void askToLeave();

    QLabel *m_progress;
    QLabel *m_prompt;
    QTimer *m_timer;
    QMediaPlayer *m_player = nullptr;
    QAudioOutput *m_output = nullptr;
    std::vector<QImage> m_left;
    std::vector<QImage> m_right;
    QString m_mediaPath;
    QString m_message;
    double m_frameRate = 25.0;
    int m_frame = 0;
    QElapsedTimer m_clock;      // playback time: the frame shown follows it (and the sound)
    QElapsedTimer m_answerClock; // from the first playback start of the trial
    bool m_accepting = false;
    bool m_audioEnabled = true;
    bool m_confirmLeave = true;
};

} // namespace lipsync::studio
