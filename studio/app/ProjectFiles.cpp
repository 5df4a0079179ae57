#include "app/ProjectFiles.h"

#include "app/Autosave.h"
#include "app/DemoProject.h"
#include "app/RecentProjects.h"
#include "context/ErrorReporter.h"
#include "document/ProjectDocument.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "util/ResourceLocator.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

namespace lipsync::studio {

namespace {

QString resourceFolders()
{
    QStringList folders;
    for (const std::string &f : ResourceLocator::folders())
        folders << QDir::toNativeSeparators(QString::fromStdString(f));
    return folders.join(QStringLiteral(", "));
}

} // namespace

ProjectFiles::ProjectFiles(ProjectDocument *document, QWidget *window, QMenu *recentMenu, TaskRunner *runner)
    : QObject(window), m_document(document), m_window(window), m_recent(new RecentProjects(recentMenu, this)),
      m_autosave(new Autosave(document, window)), m_runner(runner)
{
    connect(m_recent, &RecentProjects::openRequested, this, [this](const QString &folder) {
        if (maybeSave())
            open(folder);
    });
    // Not a message box every few minutes, but not silent either: the user's edits are only in memory.
    connect(m_autosave, &Autosave::failed, this, [this](const QString &message) {
        if (auto *window = qobject_cast<QMainWindow *>(m_window))
            window->statusBar()->showMessage(
                tr("Autosave failed (unsaved changes are only in memory; the project on disk is untouched): %1")
                    .arg(message),
                30000);
    });
}

void ProjectFiles::openWithDialog()
{
    if (!maybeSave())
        return;
    const QString start = m_document->isReadOnly() ? QDir::homePath() : m_document->folder();
    const QString file = QFileDialog::getOpenFileName(m_window, tr("Open Project"), start,
                                                      tr("LipSync projects (project.json)"));
    if (!file.isEmpty())
        open(file);
}

void ProjectFiles::newProjectWithDialog()
{
    if (!maybeSave())
        return;
    const QString folder = QFileDialog::getExistingDirectory(
        m_window, tr("New Project: the Folder of Your Clips (transcripts beside them)"), QDir::homePath());
    if (!folder.isEmpty())
        createFromMediaFolder(folder, folder);
}

Task *ProjectFiles::createFromMediaFolder(const QString &mediaFolder, const QString &projectFolder)
{
    const QString manifest = QDir(projectFolder).filePath(QString::fromLatin1(Project::kManifestName));
    if (QFileInfo::exists(manifest)) {
        ErrorReporter::report(m_window, tr("No new project was created."), manifest,
                              tr("the folder already holds a project: open it instead"));
        return nullptr;
    }
    Task *task = m_runner->start(tr("New project from %1").arg(QDir::toNativeSeparators(mediaFolder)),
                                 [this, mediaFolder, projectFolder](Feedback &) {
                                     // A damaged clip is listed and left out; the rest go in.
                                     std::vector<std::string> skipped;
                                     Project project = Project::fromMediaFolder(
                                         mediaFolder.toStdString(), projectFolder.toStdString(), &skipped);
                                     project.name = QFileInfo(projectFolder).fileName().toStdString();
                                     // A new person: the aligner that fits anyone (Model menu).
                                     project.aligner = Project::kGenericAligner;
                                     project.saveAs(projectFolder.toStdString());
                                     return TaskRunner::Commit(
                                         [this, projectFolder, skipped, project = std::move(project)]() mutable {
                                             if (!openLoaded(std::move(project), projectFolder, false))
                                                 return;
                                             m_recent->add(projectFolder);
                                             if (!skipped.empty()) {
                                                 QStringList lines;
                                                 for (const std::string &why : skipped)
                                                     lines << QString::fromStdString(why);
                                                 ErrorReporter::report(
                                                     m_window, tr("%n clip(s) could not be read and were left out.", "",
                                                                  int(skipped.size())),
                                                     QString(), lines.join(QLatin1Char('\n')));
                                             }
                                         });
                                 });
    connect(task, &Task::finished, this, [this, task](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(m_window, tr("No new project was created."), QString(), task->errorMessage());
    });
    return task;
}

bool ProjectFiles::open(const QString &path)
{
    QFileInfo info(path);
    // A project.json names its folder; anything else (even a missing path) is the folder.
    const QString folder = info.isFile() ? info.absolutePath() : info.absoluteFilePath();
    if (info.isDir() && !QFileInfo::exists(QDir(folder).filePath(QString::fromLatin1(Project::kManifestName)))
        && !ErrorReporter::isBatchMode()
        && QMessageBox::question(m_window, tr("Open Project"),
                                 tr("%1 holds no project. Create a new project from the clips in it?")
                                     .arg(QDir::toNativeSeparators(folder)))
               == QMessageBox::Yes)
        return createFromMediaFolder(folder, folder) != nullptr;
    Project project;
    try {
        project = Project::load(folder.toStdString());
    } catch (const std::exception &e) {
        ErrorReporter::report(m_window, tr("The project could not be opened."), e,
                              QDir(folder).filePath(QString::fromLatin1(Project::kManifestName)));
        return false;
    }
    if (!openLoaded(std::move(project), folder, false))
        return false;
    m_recent->add(folder);
    return true;
}

bool ProjectFiles::openLoaded(Project project, const QString &folder, bool readOnly)
{
    Autosave::Offer offer = Autosave::recoveryFor(folder, readOnly, m_window);
    if (offer.choice == Autosave::Choice::Cancel)
        return false;
    if (!offer.recovered) {
        m_document->reset(std::move(project), folder, readOnly);
        return true;
    }
    // The recovered version opens as unsaved changes, so the title shows it, Save writes it and
    // closing asks.
    m_document->reset(std::move(*offer.recovered), folder, readOnly);
    m_document->markUnsaved();
    return true;
}

bool ProjectFiles::openDemo()
{
    const QString folder = DemoProject::locate();
    if (folder.isEmpty()) {
        ErrorReporter::report(m_window, tr("The bundled demo project was not found."), QString(),
                              tr("Looked for demo/ in: %1").arg(resourceFolders()));
        return false;
    }
    Project project;
    try {
        project = DemoProject::load(folder);
    } catch (const std::exception &e) {
        ErrorReporter::report(m_window, tr("The demo project could not be opened."), e, folder);
        return false;
    }
    if (!openLoaded(std::move(project), folder, true))
        return false;
    m_recent->openedDemo();
    return true;
}

bool ProjectFiles::save()
{
    if (!m_document->isOpen())
        return false;
    if (m_document->isReadOnly())
        return saveAs();
    return saveTo(m_document->folder());
}

bool ProjectFiles::saveAs()
{
    if (!m_document->isOpen())
        return false;
    // A project is a folder: the name typed here becomes the folder.
    const QString suggested = m_document->isReadOnly() ? DemoProject::defaultSaveFolder() : m_document->folder();
    QDir().mkpath(QFileInfo(suggested).absolutePath());
    const QString folder = QFileDialog::getSaveFileName(m_window, tr("Save Project As (a folder)"), suggested,
                                                        QString(), nullptr, QFileDialog::DontConfirmOverwrite);
    if (folder.isEmpty())
        return false;
    if (QFileInfo(folder).isFile()) {
        ErrorReporter::report(m_window, tr("The project could not be saved."), folder,
                              tr("a file of that name exists; a project needs a folder"));
        return false;
    }
    if (QDir(folder).exists(QString::fromLatin1(Project::kManifestName))
        && QFileInfo(folder).canonicalFilePath() != QFileInfo(m_document->folder()).canonicalFilePath()
        && QMessageBox::question(m_window, tr("Replace Project"),
                                 tr("%1 already holds a project. Replace it?").arg(QDir::toNativeSeparators(folder)))
               != QMessageBox::Yes)
        return false;
    return saveTo(folder);
}

bool ProjectFiles::saveTo(const QString &folder)
{
    try {
        m_document->saveTo(folder);
        m_autosave->discard(); // saved: nothing unsaved is left to keep
    } catch (const std::exception &e) {
        ErrorReporter::report(m_window, tr("The project could not be saved."), e,
                              QDir(folder).filePath(QString::fromLatin1(Project::kManifestName)));
        return false;
    }
    m_recent->add(folder);
    return true;
}

bool ProjectFiles::maybeSave()
{
    if (!m_document->isModified() || ErrorReporter::isBatchMode())
        return true;
    const auto answer = QMessageBox::question(
        m_window, tr("Unsaved Changes"), tr("The project has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

} // namespace lipsync::studio
