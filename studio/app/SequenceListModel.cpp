#include "app/SequenceListModel.h"

#include "align/SpeechRecognizer.h"
#include "document/ProjectDocument.h"

#include <QApplication>
#include <QFont>
#include <QGuiApplication>
#include <QLocale>
#include <QPalette>
#include <QStyle>

namespace lipsync::studio {

SequenceListModel::SequenceListModel(ProjectDocument *document, QObject *parent)
    : QAbstractTableModel(parent), m_document(document)
{
    connect(document, &ProjectDocument::documentReset, this, [this] {
        beginResetModel();
        endResetModel();
    });
    connect(document, &ProjectDocument::sequenceChanged, this, [this](int row) {
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    });
    connect(document, &ProjectDocument::sequencesAboutToBeAdded, this,
            [this](int first, int count) { beginInsertRows({}, first, first + count - 1); });
    connect(document, &ProjectDocument::sequencesAdded, this, [this] { endInsertRows(); });
    connect(document, &ProjectDocument::sequencesAboutToBeRemoved, this,
            [this](int first, int count) { beginRemoveRows({}, first, first + count - 1); });
    connect(document, &ProjectDocument::sequencesRemoved, this, [this] { endRemoveRows(); });
}

int SequenceListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_document->sequenceCount();
}

int SequenceListModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SequenceListModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_document->sequenceCount())
        return {};
    const Sequence &s = m_document->sequence(index.row());
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        switch (index.column()) {
        case IdColumn: return QString::fromStdString(s.id);
        case FramesColumn: return s.frameCount;
        case DurationColumn:
            return role == Qt::EditRole ? QVariant(s.duration())
                                        : QVariant(tr("%1 s").arg(QLocale().toString(s.duration(), 'f', 2)));
        case TranscriptColumn: return QString::fromStdString(s.transcript);
        }
    }
    // A proposed transcript (speech recognition's words, Sequence::transcriptProposed) is shown
    // as unverified until the user edits or accepts it.
    const bool proposed = index.column() == TranscriptColumn && s.transcriptProposed;
    // A transcript its alignment found not to fit the sound (Sequence::transcriptFit) is marked
    // until the sequence is aligned again.
    const bool misfit = index.column() == TranscriptColumn && transcriptMisfit(s.transcriptFit);
    if (role == Qt::DecorationRole && misfit)
        return QApplication::style()->standardIcon(QStyle::SP_MessageBoxWarning);
    if (role == Qt::FontRole && proposed) {
        QFont font;
        font.setItalic(true);
        return font;
    }
    if (role == Qt::ForegroundRole && proposed)
        return QGuiApplication::palette().brush(QPalette::PlaceholderText);
    if (role == Qt::ToolTipRole) {
        if (misfit)
            return tr("The transcript does not fit the sound (%1 nats per frame against the aligner's best phones, "
                      "below %2): these are likely not the clip's words. Check them, then align the sequence again. "
                      "An aligner that does not know the speaker scores every transcript low: then align with the "
                      "project's own aligner, or Generic US English with Adapt to Speaker.")
                .arg(QLocale().toString(s.transcriptFit->value, 'f', 2))
                .arg(QLocale().toString(s.transcriptFit->threshold, 'f', 1));
        if (proposed) {
            QString tip = tr("Proposed by speech recognition and not checked yet: double-click to edit it, or accept "
                             "it as it is (Accept Proposed Transcript, in the Edit menu or on right-click)");
            // The recogniser's least sure words, to check first.
            if (const QString doubtful = doubtfulWords(s); !doubtful.isEmpty())
                tip += QLatin1Char('\n') + tr("Doubtful words, the most doubtful first: %1").arg(doubtful);
            return tip;
        }
        if (index.column() == TranscriptColumn)
            return tr("Double-click to edit the transcript");
        return tr("%1 — %2 frames at %3 fps")
            .arg(QString::fromStdString(s.mediaFile)).arg(s.frameCount).arg(QLocale().toString(s.frameRate, 'f', 2));
    }
    if (role == Qt::TextAlignmentRole && (index.column() == FramesColumn || index.column() == DurationColumn))
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QString SequenceListModel::doubtfulWords(const Sequence &sequence)
{
    const std::vector<std::string> words = Sequence::transcriptWords(sequence.transcript);
    if (sequence.transcriptConfidence.size() != words.size())
        return {};
    QStringList doubtful;
    for (int i : lipsync::doubtfulWords(sequence.transcriptConfidence))
        doubtful << QStringLiteral("%1 (%2)").arg(QString::fromStdString(words[size_t(i)]),
                                                  QLocale().toString(sequence.transcriptConfidence[size_t(i)], 'f', 2));
    return doubtful.join(QStringLiteral(", "));
}

bool SequenceListModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || index.column() != TranscriptColumn)
        return false;
    return m_document->requestTranscriptChange(index.row(), value.toString());
}

Qt::ItemFlags SequenceListModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (index.column() == TranscriptColumn)
        f |= Qt::ItemIsEditable;
    return f;
}

QVariant SequenceListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case IdColumn: return tr("Sequence");
    case FramesColumn: return tr("Frames");
    case DurationColumn: return tr("Duration");
    case TranscriptColumn: return tr("Transcript");
    }
    return {};
}

} // namespace lipsync::studio
