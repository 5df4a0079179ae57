#pragma once
// The results of the blind study in the form of the paper's Table 1: one row per pair of
// methods with how often each side was judged real, how often the participant could not decide,
// and the sign-test p-value; below it the Bradley–Terry ranking and the one-line summary
// ("DPDS ≈ real ≻ Brand ≻ SLDS"). Export writes both tables as CSV (StudyTally's columns).
#include <QWidget>

#include <string>

class QLabel;
class QPushButton;
class QTableWidget;

namespace lipsync {
class ForcedChoiceStudy;
class StudyTally;
} // namespace lipsync

namespace lipsync::studio {

class StudyResultsView : public QWidget
{
    Q_OBJECT
public:
    explicit StudyResultsView(QWidget *parent = nullptr);

    // Shows the tally of `study` (null: no study); Export starts in `exportFolder`.
    void setStudy(const ForcedChoiceStudy *study, const QString &exportFolder = QString());

    QTableWidget *pairTable() const { return m_pairs; }
    QTableWidget *rankingTable() const { return m_ranking; }
    QLabel *summary() const { return m_summary; }
    QPushButton *exportButton() const { return m_export; }
    // Writes the pairs table to `path` and the ranking beside it (<stem>-ranking.csv), each
    // atomically. Throws lipsync::Error naming the file.
    void exportCsv(const QString &path) const;
    static QString rankingPath(const QString &pairsPath);

private:
    void exportWithDialog();

    QLabel *m_summary;
    QTableWidget *m_pairs;
    QTableWidget *m_ranking;
    QPushButton *m_export;
    std::string m_pairsCsv;
    std::string m_rankingCsv;
    QString m_exportFolder;
};

} // namespace lipsync::studio
