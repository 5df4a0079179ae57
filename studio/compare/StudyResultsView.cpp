#include "compare/StudyResultsView.h"

#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "eval/StudyTally.h"
#include "io/AtomicFile.h"
#include "util/Error.h"

#include <QFileDialog>
#include <QDir>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lipsync::studio {

namespace {

QTableWidgetItem *cell(const QString &text, bool number)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    if (number)
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

QString pValueText(double p)
{
    // As the paper reports them: small values in scientific notation.
    return p < 1e-3 ? QString::number(p, 'e', 2) : QString::number(p, 'f', 3);
}

} // namespace

StudyResultsView::StudyResultsView(QWidget *parent)
    : QWidget(parent), m_summary(new QLabel(this)), m_pairs(new QTableWidget(this)),
      m_ranking(new QTableWidget(this)), m_export(new QPushButton(tr("Export CSV…"), this))
{
    setObjectName(QStringLiteral("studyResults"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_pairs->setColumnCount(7);
    m_pairs->setHorizontalHeaderLabels({tr("Method A"), tr("A judged real"), tr("Can't decide"),
                                        tr("B judged real"), tr("Method B"), tr("p (sign test)"),
                                        tr("p (Holm)")});
    m_ranking->setColumnCount(6);
    m_ranking->setHorizontalHeaderLabels({tr("Method"), tr("Bradley–Terry strength"), tr("Judged real"),
                                          tr("Not judged real"), tr("Can't decide"), tr("Judged real (95 % CI)")});
    for (QTableWidget *table : {m_pairs, m_ranking}) {
        table->verticalHeader()->setVisible(true);
        table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    }
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Which one is real? Pairs of methods (as in the paper's Table 1):"), this));
    layout->addWidget(m_pairs, 2);
    layout->addWidget(new QLabel(tr("Ranking:"), this));
    layout->addWidget(m_ranking, 1);
    layout->addWidget(m_summary);
    layout->addWidget(m_export, 0, Qt::AlignRight);
    connect(m_export, &QPushButton::clicked, this, &StudyResultsView::exportWithDialog);
    setStudy(nullptr);
}

void StudyResultsView::setStudy(const ForcedChoiceStudy *study, const QString &exportFolder)
{
    m_exportFolder = exportFolder;
    m_pairs->setRowCount(0);
    m_ranking->setRowCount(0);
    m_pairsCsv.clear();
    m_rankingCsv.clear();
    m_export->setEnabled(study != nullptr);
    if (!study) {
        m_summary->setText(tr("The project has no study yet: Study ▸ Set up study…"));
        return;
    }
    const StudyTally tally = StudyTally::fromStudy(*study);
    const auto name = [&](int method) { return ModelKinds::name(tally.methods[size_t(method)]); };
    m_pairs->setRowCount(int(tally.pairs.size()));
    for (int r = 0; r < int(tally.pairs.size()); ++r) {
        const PairTally &p = tally.pairs[size_t(r)];
        m_pairs->setItem(r, 0, cell(name(p.a), false));
        m_pairs->setItem(r, 1, cell(QString::number(p.preferA), true));
        m_pairs->setItem(r, 2, cell(QString::number(p.undecided), true));
        m_pairs->setItem(r, 3, cell(QString::number(p.preferB), true));
        m_pairs->setItem(r, 4, cell(name(p.b), false));
        m_pairs->setItem(r, 5, cell(p.decided() > 0 ? pValueText(p.pValue) : QStringLiteral("–"), true));
        // Adjusted over all pairs (Holm-Bonferroni, docs/models.md §6.4); the summary line uses it.
        m_pairs->setItem(r, 6, cell(p.decided() > 0 ? pValueText(p.holmPValue) : QStringLiteral("–"), true));
    }
    m_ranking->setRowCount(int(tally.ranking.size()));
    for (int r = 0; r < int(tally.ranking.size()); ++r) {
        const MethodScore &s = tally.ranking[size_t(r)];
        m_ranking->setItem(r, 0, cell(name(s.method), false));
        m_ranking->setItem(r, 1, cell(QString::number(s.strength, 'f', 3), true));
        m_ranking->setItem(r, 2, cell(QString::number(s.wins), true));
        m_ranking->setItem(r, 3, cell(QString::number(s.losses), true));
        m_ranking->setItem(r, 4, cell(QString::number(s.undecided), true));
        m_ranking->setItem(r, 5, cell(s.wins + s.losses == 0 ? QStringLiteral("–")
                                                              : tr("%1 % (%2–%3 %)")
                                                                    .arg(100 * s.realShare, 0, 'f', 0)
                                                                    .arg(100 * s.realShareLow, 0, 'f', 0)
                                                                    .arg(100 * s.realShareHigh, 0, 'f', 0),
                                      true));
    }
    m_summary->setText(tr("Participants: %1, answers: %2 (%3 still open). %4")
                           .arg(tally.participants)
                           .arg(tally.answered)
                           .arg(tally.unanswered)
                           .arg(tally.answered > 0 ? QString::fromStdString(tally.summary(0.05, [](const std::string &method) {
                                              return ModelKinds::name(method).toStdString();
                                          })) : QString()));
    if (tally.answered > 0 && tally.fewestDecided() < StudyTally::kFewAnswers)
        m_summary->setText(m_summary->text() + QLatin1Char('\n')
                           + tr("Few answers: a pair has only %1 decided (%2 or more are needed before a ranking "
                                "says much); read the intervals, not the strengths.")
                                 .arg(tally.fewestDecided())
                                 .arg(StudyTally::kFewAnswers));
    m_pairsCsv = tally.pairsCsv();
    m_rankingCsv = tally.rankingCsv();
}

QString StudyResultsView::rankingPath(const QString &pairsPath)
{
    const QFileInfo info(pairsPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral("-ranking.csv"));
}

void StudyResultsView::exportCsv(const QString &path) const
{
    if (m_pairsCsv.empty())
        throw Error("there are no study results to export", path.toStdString());
    writeFileAtomically(path.toStdString(), m_pairsCsv);
    writeFileAtomically(rankingPath(path).toStdString(), m_rankingCsv);
}

void StudyResultsView::exportWithDialog()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export study results"),
                                                      QDir(m_exportFolder).filePath(QStringLiteral("table1.csv")),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    try {
        exportCsv(path);
    } catch (const Error &e) {
        ErrorReporter::report(this, tr("Export study results"), e);
    }
}

} // namespace lipsync::studio
