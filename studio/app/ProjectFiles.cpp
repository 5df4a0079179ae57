#include "app/ProjectFiles.h"

#include "app/DemoProject.h"
#include "app/ErrorReporter.h"
#include "app/ProjectDocument.h"
#include "app/RecentProjects.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

namespace lipsync::studio {

ProjectFiles::ProjectFiles(ProjectDocument *document, QWidget *window, QMenu *recentMenu)
    : QObject(window), m_document(document), m_window(window), m_recent(new RecentProjects(recentMenu, this))
{
    connect(m_recent, &RecentProjects::openRequested, this, [this](const QString &folder) {
        if (maybeSave())
            open(folder);
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

bool ProjectFiles::open(const QString &path)
{
    QFileInfo info(path);
    // A project.json names its folder; anything else (even a missing path) is the folder.
    const QString folder = info.isFile() ? info.absolutePath() : info.absoluteFilePath();
    try {
        Project project = Project::load(folder.toStdString());
        m_document->reset(std::move(project), folder, false);
    } catch (const std::exception &e) {
        ErrorReporter::report(m_window, tr("The project could not be opened."), e,
                              QDir(folder).filePath(QString::fromLatin1(Project::kManifestName)));
        return false;
    }
    m_recent->add(folder);
    return true;
}

bool ProjectFiles::openDemo()
{
    const QString folder = DemoProject::locate();
    if (folder.isEmpty()) {
        ErrorReporter::report(m_window, tr("The bundled demo project was not found."), QString(),
                              tr("Looked in $LIPSYNC_DEMO_DIR, <prefix>/share/lipsync/demo and the source tree."));
        return false;
    }
    try {
        m_document->reset(DemoProject::load(folder), folder, true);
    } catch (const std::exception &e) {
        ErrorReporter::report(m_window, tr("The demo project could not be opened."), e, folder);
        return false;
    }
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
