#include "compare/StudyController.h"

#include "compare/ParticipantSession.h"
#include "compare/StudyClipRenderer.h"
#include "compare/StudyResultsView.h"
#include "compare/StudySetupDialog.h"
#include "context/ErrorReporter.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "util/Error.h"

#include <QAction>
#include <QDialog>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QVBoxLayout>

#include <algorithm>

namespace lipsync::studio {

StudyController::StudyController(StudioContext *context, std::function<bool()> saveProject, QWidget *window)
    : QObject(window), m_context(context), m_saveProject(std::move(saveProject)), m_window(window), m_menu(new QMenu(tr("&Study"), window)),
      m_setUp(m_menu->addAction(tr("&Set Up Study…"))), m_run(m_menu->addAction(tr("&Run Participant…"))),
      m_results(m_menu->addAction(tr("Study &Results")))
{
    setObjectName(QStringLiteral("studyController"));
    connect(m_setUp, &QAction::triggered, this, &StudyController::setUpWithDialog);
    connect(m_run, &QAction::triggered, this, &StudyController::runWithDialog);
    connect(m_results, &QAction::triggered, this, [this] { showResults(); });
    ProjectDocument *document = m_context->document();
    // The videos depend on the features, phones, models and lip closure: a change renders afresh.
    for (auto signal : {&ProjectDocument::documentReset, &ProjectDocument::modelsChanged,
                        &ProjectDocument::locationChanged})
        connect(document, signal, this, [this] { m_renderer.reset(); });
    connect(document, &ProjectDocument::sequenceChanged, this, [this] { m_renderer.reset(); });
    connect(m_context, &StudioContext::lipClosureChanged, this, [this] { m_renderer.reset(); });
    connect(document, &ProjectDocument::studyChanged, this, &StudyController::refresh);
    connect(document, &ProjectDocument::documentReset, this, &StudyController::refresh);
    refresh();
}

StudyController::~StudyController() = default;

ParticipantSession *StudyController::participantSession() const
{
    return m_session;
}

void StudyController::refresh()
{
    const ProjectDocument *document = m_context->document();
    m_setUp->setEnabled(document->isOpen());
    m_run->setEnabled(document->isOpen() && document->project().study.has_value());
    if (m_resultsView)
        m_resultsView->setStudy(document->project().study ? &*document->project().study : nullptr,
                                document->exportFolder());
}

QString StudyController::nextPseudonym() const
{
    const auto &study = m_context->document()->project().study;
    for (int n = 1;; ++n) {
        const QString name = QStringLiteral("P%1").arg(n, 2, 10, QLatin1Char('0'));
        bool taken = false;
        if (study)
            for (const StudySession &s : study->sessions())
                taken = taken || s.participant == name.toStdString();
        if (!taken)
            return name;
    }
}

void StudyController::setUpWithDialog()
{
    ProjectDocument *document = m_context->document();
    if (document->project().study) {
        int answers = 0;
        for (const StudySession &s : document->project().study->sessions())
            answers += s.answered();
        if (answers > 0
            && QMessageBox::question(m_window, tr("Set up study"),
                                     tr("The current study has %n answer(s). Replace it with a new study? "
                                        "(Edit ▸ Undo brings it back.)",
                                        nullptr, answers))
                   != QMessageBox::Yes)
            return;
    }
    StudySetupDialog dialog(document->project(), m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (const std::optional<ForcedChoiceStudy> study = dialog.study())
        document->requestStudy(study, tr("Set up study"));
}

bool StudyController::ensureSaved()
{
    ProjectDocument *document = m_context->document();
    if (document->isStudySaved())
        return true;
    // Answers are written to the project's study file after every trial, so the project must
    // live in a folder of its own and be saved with the study first.
    if (!ErrorReporter::isBatchMode()
        && QMessageBox::question(m_window, tr("Run participant"),
                                 tr("The project must be saved with the study before a participant starts "
                                    "(every answer is saved at once). Save now?"))
               != QMessageBox::Yes)
        return false;
    return m_saveProject() && document->isStudySaved();
}

ParticipantSession *StudyController::startParticipant(const QString &pseudonym, bool fullScreen)
{
    ProjectDocument *document = m_context->document();
    if (m_session)
        return nullptr; // one participant at a time
    if (!document->project().study) {
        ErrorReporter::report(m_window, tr("Run participant"), QString(), tr("The project has no study yet."));
        return nullptr;
    }
    if (!ensureSaved())
        return nullptr;
    const ForcedChoiceStudy &study = *document->project().study;
    int session = -1;
    for (int i = 0; i < int(study.sessions().size()); ++i)
        if (study.sessions()[std::size_t(i)].participant == pseudonym.toStdString())
            session = i;
    try {
        if (session < 0)
            session = document->addStudyParticipant(pseudonym);
        else if (study.sessions()[std::size_t(session)].complete())
            throw Error("participant \"" + pseudonym.toStdString() + "\" has answered every trial");
    } catch (const Error &e) {
        ErrorReporter::report(m_window, tr("Run participant"), e);
        return nullptr;
    }
    if (!m_renderer)
        m_renderer = std::make_shared<StudyClipRenderer>(document->project(), m_context->closesLips());
    m_session = new ParticipantSession(m_context, m_window, session, m_renderer, this);
    connect(m_session, &ParticipantSession::finished, m_session, &QObject::deleteLater);
    m_session->start(fullScreen);
    return m_session;
}

void StudyController::runWithDialog()
{
    const auto &study = m_context->document()->project().study;
    if (!study)
        return;
    // A new participant by default; unfinished sessions can be resumed.
    QStringList items{tr("New participant: %1").arg(nextPseudonym())};
    QStringList names{nextPseudonym()};
    for (const StudySession &s : study->sessions())
        if (!s.complete()) {
            items << tr("Continue %1 (%2 of %3 answered)")
                         .arg(QString::fromStdString(s.participant))
                         .arg(s.answered())
                         .arg(s.trials.size());
            names << QString::fromStdString(s.participant);
        }
    // Wide enough that its title and the longest entry are read whole, in every language.
    QInputDialog dialog(m_window);
    dialog.setWindowTitle(tr("Run participant"));
    dialog.setLabelText(tr("Participant:"));
    dialog.setComboBoxItems(items);
    dialog.setComboBoxEditable(false);
    dialog.setMinimumWidth(std::max(420, dialog.fontMetrics().horizontalAdvance(items.join(QString())) / 2));
    if (dialog.exec() == QDialog::Accepted)
        startParticipant(names.value(items.indexOf(dialog.textValue())));
}

StudyResultsView *StudyController::showResults()
{
    if (!m_resultsWindow) {
        m_resultsWindow = new QDialog(m_window);
        m_resultsWindow->setWindowTitle(tr("Study results"));
        m_resultsWindow->resize(760, 560);
        m_resultsView = new StudyResultsView(m_resultsWindow);
        auto *layout = new QVBoxLayout(m_resultsWindow);
        layout->addWidget(m_resultsView);
        refresh();
    }
    m_resultsWindow->show();
    m_resultsWindow->raise();
    return m_resultsView;
}

} // namespace lipsync::studio
