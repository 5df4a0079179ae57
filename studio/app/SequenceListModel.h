#pragma once
// The project's sequences as a table (id, frames, duration, transcript). The transcript column
// is editable; edits go through ProjectDocument::requestTranscriptChange, so they are undoable.
// A transcript proposed by speech recognition is shown as unverified (italic, muted, a tooltip
// saying so) until edited or accepted.
#include <QAbstractTableModel>

namespace lipsync {
struct Sequence;
}

namespace lipsync::studio {

class ProjectDocument;

class SequenceListModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { IdColumn, FramesColumn, DurationColumn, TranscriptColumn, ColumnCount };

    explicit SequenceListModel(ProjectDocument *document, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // The doubtful words of `sequence`'s proposed transcript (Sequence::transcriptConfidence
    // below kDoubtfulWordConfidence), the most doubtful first, as "word (0.12), ..."; empty if none.
    static QString doubtfulWords(const Sequence &sequence);

private:
    ProjectDocument *m_document;
};

} // namespace lipsync::studio
