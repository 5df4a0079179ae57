#include "compare/StudySetupDialog.h"

#include "compare/StudyClipRenderer.h"
#include "context/ModelKinds.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <random>

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
    : QDialog(parent), m_pool(candidateUtterances(project)), m_methods(new QListWidget(this)),
      m_utterances(new QSpinBox(this)), m_repeats(new QSpinBox(this)), m_seed(new QSpinBox(this)),
      m_summary(new QLabel(this))
{
    setWindowTitle(tr("Set up blind study"));
    for (const std::string &method : StudyClipRenderer::availableMethods(project)) {
        auto *item = new QListWidgetItem(methodTitle(method), m_methods);
        item->setData(Qt::UserRole, QString::fromStdString(method));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Checked);
    }
    m_utterances->setRange(m_pool.empty() ? 0 : 1, int(m_pool.size()));
    m_utterances->setValue(int(m_pool.size()));
    m_repeats->setRange(1, 10);
    m_seed->setRange(0, 1'000'000'000);
    m_seed->setValue(2007);
    m_summary->setWordWrap(true);

    auto *form = new QFormLayout(this);
    form->addRow(tr("Methods to compare:"), m_methods);
    form->addRow(tr("Utterances:"), m_utterances);
    form->addRow(tr("Each pair shown (× 2, sides swapped):"), m_repeats);
    form->addRow(tr("Random seed:"), m_seed);
    form->addRow(m_summary);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_methods, &QListWidget::itemChanged, this, &StudySetupDialog::updateSummary);
    connect(m_utterances, &QSpinBox::valueChanged, this, &StudySetupDialog::updateSummary);
    connect(m_repeats, &QSpinBox::valueChanged, this, &StudySetupDialog::updateSummary);
    updateSummary();
}

std::vector<std::string> StudySetupDialog::candidateUtterances(const Project &project)
{
    std::vector<std::string> ids;
    for (const Sequence &s : project.sequences)
        if (s.features.rows() > 0 && !s.phones.isEmpty())
            ids.push_back(s.id);
    return ids;
}

std::vector<std::string> StudySetupDialog::drawUtterances(std::vector<std::string> pool, int count,
                                                          std::uint64_t seed)
{
    // Fisher–Yates with the raw engine (reproducible on every standard library), then the first
    // `count` in project order so the list reads like the project.
    std::mt19937_64 rng(seed);
    std::vector<size_t> order(pool.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    for (size_t i = order.size(); i > 1; --i)
        std::swap(order[i - 1], order[size_t(rng() % i)]);
    order.resize(std::min(order.size(), size_t(std::max(count, 0))));
    std::sort(order.begin(), order.end());
    std::vector<std::string> drawn;
    for (size_t i : order)
        drawn.push_back(pool[i]);
    return drawn;
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
    try {
        return ForcedChoiceStudy(methods, drawUtterances(m_pool, m_utterances->value(), std::uint64_t(m_seed->value())),
                                 std::uint64_t(m_seed->value()), m_repeats->value());
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
                           .arg(design->trialsPerSession()));
}

} // namespace lipsync::studio
