#pragma once
// The project's pronunciation overrides (Project::pronunciations): a table of word -> ARPAbet
// phones with where each came from — the project, or espeak-ng's guess for a word outside the
// CMU dictionary met during alignment — and a line to set or remove one. Input is checked
// against the 41-phone set before anything changes; each change is one step on the document's
// undo stack (ProjectDocument::requestPronunciations), so Edit > Undo reverts it. Non-modal:
// it follows the document (undo, another project) while open.
#include <QDialog>

#include <map>
#include <string>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace lipsync::studio {

class ProjectDocument;

class PronunciationsDialog : public QDialog
{
    Q_OBJECT
public:
    PronunciationsDialog(ProjectDocument *document, QWidget *parent = nullptr);

    // espeak-ng's guesses (word -> phones) from the alignments so far; shown until overridden.
    void setGuesses(const std::map<std::string, std::string> &guesses);

    // The canonical form of user input: `word` normalised (lower case, surrounding punctuation
    // dropped; one word), `phones` as PhoneSet labels separated by single spaces. Empty strings
    // and a reason in *error when not acceptable.
    static std::string canonicalWord(const QString &word, QString *error);
    static std::string canonicalPhones(const QString &phones, QString *error);

    QTableWidget *table() const { return m_table; }
    QLineEdit *wordEdit() const { return m_word; }
    QLineEdit *phonesEdit() const { return m_phones; }
    QPushButton *setButton() const { return m_set; }
    QPushButton *removeButton() const { return m_remove; }
    QLabel *messageLabel() const { return m_message; }

public slots:
    // Sets the override of the word in the line edits (validated); false if refused or unchanged.
    bool applyEntry();
    // Removes the override of the word in the line edit.
    bool removeEntry();

private:
    void refresh();
    void showMessage(const QString &text, bool error);

    ProjectDocument *m_document;
    std::map<std::string, std::string> m_guesses;
    QTableWidget *m_table;
    QLineEdit *m_word;
    QLineEdit *m_phones;
    QPushButton *m_set;
    QPushButton *m_remove;
    QLabel *m_message;
};

} // namespace lipsync::studio
