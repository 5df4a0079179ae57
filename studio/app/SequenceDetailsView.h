#pragma once
// Facts about the current sequence under the sequence list: media file, frames and rate,
// duration, audio, its transcript (how many words, or proposed and not checked yet), timed words,
// and how many frames carry landmarks.
#include <QWidget>

class QLabel;

namespace lipsync {
struct Sequence;
}

namespace lipsync::studio {

struct SequenceMedia;

class SequenceDetailsView : public QWidget
{
    Q_OBJECT
public:
    explicit SequenceDetailsView(QWidget *parent = nullptr);

    void showSequence(const Sequence &sequence, const QString &mediaPath, const SequenceMedia &media);
    void clear();

private:
    QLabel *m_title;
    QLabel *m_media;
    QLabel *m_video;
    QLabel *m_audio;
    QLabel *m_transcript;
    QLabel *m_words;
    QLabel *m_landmarks;
};

} // namespace lipsync::studio
