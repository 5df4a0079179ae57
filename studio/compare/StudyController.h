#pragma once
// The studio's Study menu (the blind study of the paper's §4, Table 1): set up the study
// (an undoable edit of the project document), run a participant in the full-screen participant
// mode, and show the results (Table 1 with sign tests, Bradley–Terry ranking, CSV export).
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <memory>

class QAction;
class QDialog;
class QMenu;

namespace lipsync::studio {

class ParticipantSession;
class StudioContext;
class StudyClipRenderer;
class StudyResultsView;

class StudyController : public QObject
{
    Q_OBJECT
public:
    // The study of the context's document; `saveProject` saves it before a participant starts
    // (true once saved), `window` parents the menu and the dialogs.
    StudyController(StudioContext *context, std::function<bool()> saveProject, QWidget *window);
    ~StudyController() override;

    QMenu *menu() const { return m_menu; }
    QAction *setUpAction() const { return m_setUp; }
    QAction *runAction() const { return m_run; }
    QAction *resultsAction() const { return m_results; }

    // Starts participant mode for `pseudonym`: a new participant gets a fresh session (own random
    // order); an unfinished one resumes. The study must be saved with the project first.
    // Returns the running session, or null (with a message) if it cannot start.
    ParticipantSession *startParticipant(const QString &pseudonym, bool fullScreen = true);
    ParticipantSession *participantSession() const;
    // The results window (created on first use) and its view.
    StudyResultsView *showResults();
    // The next free pseudonym: P01, P02, ...
    QString nextPseudonym() const;

public slots:
    void setUpWithDialog();
    void runWithDialog();

private:
    bool ensureSaved();
    void refresh();

    StudioContext *m_context;
    std::function<bool()> m_saveProject;
    QWidget *m_window;
    QMenu *m_menu;
    QAction *m_setUp;
    QAction *m_run;
    QAction *m_results;
    QPointer<QDialog> m_resultsWindow;
    StudyResultsView *m_resultsView = nullptr;
    QPointer<ParticipantSession> m_session;
    std::shared_ptr<StudyClipRenderer> m_renderer;
};

} // namespace lipsync::studio
