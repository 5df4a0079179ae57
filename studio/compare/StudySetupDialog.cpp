#include "compare/StudySetupDialog.h"

#include "compare/StudyClipRenderer.h"
#include "context/ModelKinds.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>

namespace lipsync::studio {

namespace {

QString methodTitle(const std::string &method)
{
    if (method == StudyClipRenderer::kRealMethod)
        return StudySetupDialog::tr("Real (the recorded video)");
    return ModelKinds::name(method);
}

} // namespace

StudySetupDialog::StudySetupDialog(const Project &project, QWidget *parent)
    : QDialog(parent), m_pool(ForcedChoiceStudy::candidateUtterances(project)), m_methods(new QListWidget(this)),
      m_utterances(new QSpinBox(this)), m_repeats(new QSpinBox(this)), m_seed(new QSpinBox(this)),
      m_holdOut(new QCheckBox(tr("Train each model without these utterances (the paper's design)"), this)),
      m_summary(new QLabel(this))
{
    setWindowTitle(tr("Set up blind study"));
    for (const std::string &method : StudyClipRenderer::availableMethods(project)) {
        auto *item = new QListWidgetItem(methodTitle(method), m_methods);
        item->setData(Qt::UserRole, QString::fromStdString(method));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Checked);
    }
    // Held out by default, as the paper's 80 unseen sequences were: a fifth of the pool, the rest
    // left to train on.
    m_holdOut->setObjectName(QStringLiteral("holdOutUtterances"));
    m_holdOut->setChecked(true);
    m_holdOut->setToolTip(tr("Each model is retrained, with the settings its file records, on the project's other "
                             "sequences: viewers judge speech the models have not seen."));
    m_utterances->setRange(m_pool.empty() ? 0 : 1, std::max(1, int(m_pool.size()) - 1));
    m_utterances->setValue(ForcedChoiceStudy::defaultHeldOutCount(int(m_pool.size())));
    m_repeats->setRange(1, 10);
    m_seed->setRange(0, 1'000'000'000);
    m_seed->setValue(2007);
    m_summary->setWordWrap(true);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Methods to compare:"), m_methods);
    form->addRow(tr("Utterances:"), m_utterances);
    form->addRow(tr("Each pair shown (× 2, sides swapped):"), m_repeats);
    form->addRow(tr("Random seed:"), m_seed);
    form->addRow(m_holdOut);
    form->addRow(m_summary);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_methods, &QListWidget::itemChanged, this, &StudySetupDialog::updateSummary);
    connect(m_utterances, &QSpinBox::valueChanged, this, &StudySetupDialog::updateSummary);
    connect(m_repeats, &QSpinBox::valueChanged, this, &StudySetupDialog::updateSummary);
    connect(m_holdOut, &QCheckBox::toggled, this, [this](bool on) {
        m_utterances->setMaximum(std::max(1, int(m_pool.size()) - (on ? 1 : 0)));
        updateSummary();
    });
    updateSummary();
}

std::optional<ForcedChoiceStudy> StudySetupDialog::study(QString *problem) const
{
    std::vector<std::string> methods;
    for (int i = 0; i < m_methods->count(); ++i)
        if (m_methods->item(i)->checkState() == Qt::Checked)
            methods.push_back(m_methods->item(i)->data(Qt::UserRole).toString().toStdString());
    if (methods.size() < 2) {
        if (problem)
            *problem = tr("Choose at least two methods (train models in the Models panel).");
        return std::nullopt;
    }
    if (m_pool.empty()) {
        if (problem)
            *problem = tr("No sequence has both features and phones yet.");
        return std::nullopt;
    }
    if (m_holdOut->isChecked() && m_utterances->value() >= int(m_pool.size())) {
        if (problem)
            *problem = tr("Holding out every utterance leaves nothing to train the models on.");
        return std::nullopt;
    }
    try {
        ForcedChoiceStudy design(methods, ForcedChoiceStudy::drawUtterances(m_pool, m_utterances->value(), std::uint64_t(m_seed->value())),
                                 std::uint64_t(m_seed->value()), m_repeats->value());
        design.setHoldsOutUtterances(m_holdOut->isChecked());
        return design;
    } catch (const Error &e) {
        if (problem)
            *problem = QString::fromStdString(e.reason());
        return std::nullopt;
    }
}

void StudySetupDialog::updateSummary()
{
    QString problem;
    const std::optional<ForcedChoiceStudy> design = study(&problem);
    if (m_ok)
        m_ok->setEnabled(bool(design));
    if (!design) {
        m_summary->setText(problem);
        return;
    }
    const int m = int(design->methods().size());
    m_summary->setText(tr("%1 pairs of methods, each shown %2 times with sides swapped: %3 trials per "
                          "participant, in a fresh random order for each participant.")
                           .arg(m * (m - 1) / 2)
                           .arg(2 * design->repeats())
                           .arg(design->trialsPerSession())
                       + QLatin1Char(' ')
                       + (design->holdsOutUtterances()
                              ? tr("The models are retrained without these utterances before the first trial.")
                              : tr("Warning: the models were trained on these utterances, so viewers judge speech "
                                   "the models have seen; the paper's study held its 80 sequences out.")));
}

} // namespace lipsync::studio
