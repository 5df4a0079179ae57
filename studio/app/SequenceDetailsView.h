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

class ElidedLabel;
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
    ElidedLabel *m_media;
    ElidedLabel *m_video;
    ElidedLabel *m_audio;
    ElidedLabel *m_transcript;
    ElidedLabel *m_words;
    ElidedLabel *m_landmarks;
};

} // namespace lipsync::studio
