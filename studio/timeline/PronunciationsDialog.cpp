#include "timeline/PronunciationsDialog.h"

#include "align/PronunciationDictionary.h"
#include "document/ProjectDocument.h"
#include "util/PhoneSet.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lipsync::studio {

PronunciationsDialog::PronunciationsDialog(ProjectDocument *document, QWidget *parent)
    : QDialog(parent), m_document(document), m_table(new QTableWidget(0, 3, this)), m_word(new QLineEdit(this)),
      m_phones(new QLineEdit(this)), m_set(new QPushButton(tr("Set"), this)),
      m_remove(new QPushButton(tr("Remove"), this)), m_message(new QLabel(this))
{
    setWindowTitle(tr("Pronunciations"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("Words are pronounced from this list first, then from the CMU dictionary, "
                                "then guessed by espeak-ng. Phones are ARPAbet (AA … ZH, sil, br)."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    m_table->setHorizontalHeaderLabels({tr("Word"), tr("Phones"), tr("Source")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    layout->addWidget(m_table, 1);

    auto *form = new QFormLayout;
    m_word->setPlaceholderText(tr("word"));
    m_phones->setPlaceholderText(tr("e.g. L IH P S IH NG K"));
    form->addRow(tr("Word:"), m_word);
    form->addRow(tr("Phones:"), m_phones);
    layout->addLayout(form);
    auto *row = new QHBoxLayout;
    row->addWidget(m_message, 1);
    row->addWidget(m_set);
    row->addWidget(m_remove);
    layout->addLayout(row);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    layout->addWidget(buttons);
    m_message->setWordWrap(true);
    m_set->setDefault(true);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(m_set, &QPushButton::clicked, this, &PronunciationsDialog::applyEntry);
    connect(m_remove, &QPushButton::clicked, this, &PronunciationsDialog::removeEntry);
    connect(m_phones, &QLineEdit::returnPressed, this, &PronunciationsDialog::applyEntry);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto items = m_table->selectedItems();
        if (items.isEmpty())
            return;
        const int r = items.front()->row();
        m_word->setText(m_table->item(r, 0)->text());
        m_phones->setText(m_table->item(r, 1)->text());
    });
    connect(m_document, &ProjectDocument::pronunciationsChanged, this, &PronunciationsDialog::refresh);
    connect(m_document, &ProjectDocument::documentReset, this, &PronunciationsDialog::refresh);
    resize(480, 420);
    refresh();
}

void PronunciationsDialog::setGuesses(const std::map<std::string, std::string> &guesses)
{
    m_guesses = guesses;
    refresh();
}

std::string PronunciationsDialog::canonicalWord(const QString &word, QString *error)
{
    const QString trimmed = word.trimmed();
    const std::string key = PronunciationDictionary::normalizeWord(trimmed.toStdString());
    if (trimmed.contains(QRegularExpression(QStringLiteral("\\s"))) || key.empty()) {
        *error = tr("Enter one word.");
        return {};
    }
    return key;
}

std::string PronunciationsDialog::canonicalPhones(const QString &phones, QString *error)
{
    std::string out;
    for (const QString &token : phones.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts)) {
        const int index = PhoneSet::index(token.toStdString());
        if (index < 0) {
            *error = tr("'%1' is not one of the 41 phones (ARPAbet AA … ZH, sil, br).").arg(token);
            return {};
        }
        if (!out.empty())
            out += ' ';
        out += PhoneSet::label(index);
    }
    if (out.empty())
        *error = tr("Enter the phones of the word.");
    return out;
}

bool PronunciationsDialog::applyEntry()
{
    QString error;
    const std::string word = canonicalWord(m_word->text(), &error);
    const std::string phones = word.empty() ? std::string() : canonicalPhones(m_phones->text(), &error);
    if (word.empty() || phones.empty()) {
        showMessage(error, true);
        return false;
    }
    std::map<std::string, std::string> next = m_document->project().pronunciations;
    next[word] = phones;
    const QString w = QString::fromStdString(word);
    if (!m_document->requestPronunciations(next, tr("Set Pronunciation of %1").arg(w))) {
        showMessage(tr("No change."), false);
        return false;
    }
    showMessage(tr("'%1' is pronounced %2 in this project.").arg(w, QString::fromStdString(phones)), false);
    return true;
}

bool PronunciationsDialog::removeEntry()
{
    QString error;
    const std::string word = canonicalWord(m_word->text(), &error);
    std::map<std::string, std::string> next = m_document->project().pronunciations;
    if (word.empty() || next.erase(word) == 0) {
        showMessage(word.empty() ? error : tr("The project has no pronunciation for '%1'.").arg(m_word->text()), true);
        return false;
    }
    return m_document->requestPronunciations(next, tr("Remove Pronunciation of %1").arg(QString::fromStdString(word)));
}

void PronunciationsDialog::showMessage(const QString &text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c0392b;") : QString());
}

void PronunciationsDialog::refresh()
{
    const auto &overrides = m_document->project().pronunciations;
    m_table->setRowCount(0);
    auto addRow = [this](const std::string &word, const std::string &phones, const QString &source, bool guess) {
        const int r = m_table->rowCount();
        m_table->insertRow(r);
        const QStringList cells{QString::fromStdString(word), QString::fromStdString(phones), source};
        for (int c = 0; c < 3; ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            if (guess) {
                QFont f = item->font();
                f.setItalic(true);
                item->setFont(f);
            }
            m_table->setItem(r, c, item);
        }
    };
    for (const auto &[word, phones] : overrides)
        addRow(word, phones, tr("project"), false);
    for (const auto &[word, phones] : m_guesses)
        if (!overrides.count(word))
            addRow(word, phones, tr("espeak-ng guess"), true);
    m_table->resizeColumnsToContents();
}

} // namespace lipsync::studio
