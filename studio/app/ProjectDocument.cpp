#include "app/ProjectDocument.h"

#include "app/SetTranscriptCommand.h"
#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

namespace lipsync::studio {

ProjectDocument::ProjectDocument(QUndoStack *undoStack, QObject *parent)
    : QObject(parent), m_undo(undoStack)
{
}

bool ProjectDocument::isModified() const
{
    return m_open && !m_undo->isClean();
}

void ProjectDocument::reset(Project project, const QString &folder, bool readOnly)
{
    m_project = std::move(project);
    m_folder = folder;
    m_project.setFolder(folder.toStdString());
    m_readOnly = readOnly;
    m_open = true;
    m_undo->clear();
    m_undo->setClean();
    emit documentReset();
    emit locationChanged();
}

QString ProjectDocument::mediaPath(int row) const
{
    return QString::fromStdString(m_project.resolve(sequence(row).mediaFile));
}

void ProjectDocument::saveTo(const QString &folder)
{
    const bool moving = QFileInfo(folder).absoluteFilePath() != QFileInfo(m_folder).absoluteFilePath();
    if (m_readOnly && moving) {
        // The bundled demo may move or vanish with the installation: its copy takes the
        // (small) clips along, so it stays complete on its own.
        const QDir target(folder);
        for (const Sequence &s : m_project.sequences) {
            const QString relative = QString::fromStdString(s.mediaFile);
            const QString from = QString::fromStdString(m_project.resolve(s.mediaFile));
            const QString to = target.filePath(relative);
            if (QFileInfo(relative).isAbsolute() || !QFileInfo::exists(from) || QFileInfo::exists(to))
                continue;
            if (!QDir().mkpath(QFileInfo(to).absolutePath()) || !QFile::copy(from, to))
                throw Error("cannot copy the media file into the project", to.toStdString());
        }
        // Relative paths now hold in the new folder as they are: save from there.
        Project copy = m_project;
        copy.setFolder(folder.toStdString());
        copy.saveAs(folder.toStdString());
        m_project = std::move(copy);
    } else {
        // A user's project keeps referring to its media where they are (paths rebased).
        m_project.saveAs(folder.toStdString());
    }
    m_folder = QString::fromStdString(m_project.folder());
    m_readOnly = false;
    m_undo->setClean();
    emit locationChanged();
}

bool ProjectDocument::requestTranscriptChange(int row, const QString &transcript)
{
    if (row < 0 || row >= sequenceCount())
        return false;
    const QString trimmed = transcript.simplified();
    const QString old = QString::fromStdString(sequence(row).transcript);
    if (trimmed == old)
        return false;
    m_undo->push(new SetTranscriptCommand(this, row, old, trimmed));
    return true;
}

void ProjectDocument::applyTranscript(int row, const QString &transcript)
{
    m_project.sequences.at(std::size_t(row)).transcript = transcript.toStdString();
    emit sequenceChanged(row);
}

} // namespace lipsync::studio
