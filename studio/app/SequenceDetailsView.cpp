#include "app/SequenceDetailsView.h"

#include "widgets/ElidedLabel.h"

#include "align/Lexicon.h"
#include "context/SequenceMedia.h"
#include "project/Sequence.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>

namespace lipsync::studio {

SequenceDetailsView::SequenceDetailsView(QWidget *parent)
    : QWidget(parent), m_title(new QLabel(this)), m_media(new ElidedLabel(this)), m_video(new ElidedLabel(this)),
      m_audio(new ElidedLabel(this)), m_transcript(new ElidedLabel(this)), m_words(new ElidedLabel(this)),
      m_landmarks(new ElidedLabel(this))
{
    auto *form = new QFormLayout(this);
    form->setContentsMargins(8, 8, 8, 8);
    form->setLabelAlignment(Qt::AlignRight);
    QFont bold = m_title->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    m_title->setFont(bold);
    form->addRow(m_title);
    form->addRow(tr("Media:"), m_media);
    form->addRow(tr("Video:"), m_video);
    form->addRow(tr("Audio:"), m_audio);
    m_transcript->setObjectName(QStringLiteral("transcriptDetails"));
    form->addRow(tr("Transcript:"), m_transcript);
    form->addRow(tr("Words:"), m_words);
    form->addRow(tr("Landmarks:"), m_landmarks);
    clear();
}

void SequenceDetailsView::clear()
{
    m_title->setText(tr("No sequence"));
    for (ElidedLabel *l : {m_media, m_video, m_audio, m_transcript, m_words, m_landmarks})
        l->clear();
}

void SequenceDetailsView::showSequence(const Sequence &sequence, const QString &mediaPath,
                                       const SequenceMedia &media)
{
    const QLocale locale;
    m_title->setText(QString::fromStdString(sequence.id));
    m_media->setText(QFileInfo(mediaPath).fileName());
    m_media->setToolTip(QDir::toNativeSeparators(mediaPath));
    const QSize size = media.frames.isEmpty() ? QSize() : media.frames.front().size();
    if (media.audioOnly)
        m_video->setText(tr("sound only, %1 frames at %2 fps")
                             .arg(media.frameCount())
                             .arg(locale.toString(media.frameRate, 'f', 2)));
    else
        m_video->setText(tr("%1 frames, %2 fps, %3×%4")
                             .arg(media.frameCount())
                             .arg(locale.toString(media.frameRate, 'f', 2))
                             .arg(size.width())
                             .arg(size.height()));
    if (media.peaks)
        m_audio->setText(tr("%1 s, decoded at %2 Hz mono")
                             .arg(locale.toString(media.peaks->duration(), 'f', 2))
                             .arg(media.peaks->sampleRate()));
    else
        m_audio->setText(tr("none (%1)").arg(media.audioError));
    const std::size_t words = Lexicon::splitWords(sequence.transcript).size();
    const bool proposed = words > 0 && sequence.transcriptProposed;
    const bool misfit = words > 0 && transcriptMisfit(sequence.transcriptFit);
    m_transcript->setText(words == 0 ? tr("none")
                          : misfit   ? tr("%1 words; does not fit the sound").arg(words)
                          : proposed ? tr("proposed, not checked")
                                     : tr("%1 words").arg(words));
    QFont font = m_transcript->font();
    font.setItalic(proposed);
    m_transcript->setFont(font);
    m_transcript->setToolTip(misfit ? tr("Its alignment found other words in the sound (%1 nats per frame, below %2): "
                                         "check the transcript, then align the sequence again")
                                          .arg(locale.toString(sequence.transcriptFit->value, 'f', 2))
                                          .arg(locale.toString(sequence.transcriptFit->threshold, 'f', 1))
                             : proposed ? tr("Proposed by speech recognition: edit it in the list's Transcript column, "
                                           "or accept it as it is")
                                      : QString());
    int spoken = 0;
    for (const Interval &iv : sequence.words.intervals)
        spoken += PhoneSet::isSilence(iv.label) ? 0 : 1;
    m_words->setText(tr("%1 timed words").arg(spoken));
    m_landmarks->setText(tr("%1 of %2 frames").arg(sequence.landmarks.size()).arg(sequence.frameCount));
}

} // namespace lipsync::studio
