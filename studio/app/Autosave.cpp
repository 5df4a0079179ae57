#include "app/Autosave.h"

#include "context/ErrorReporter.h"
#include "document/ProjectDocument.h"
#include "project/ProjectManifest.h"
#include "tasks/FencedJob.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QThreadPool>
#include <QtDebug>

namespace lipsync::studio {

namespace {

Autosave::Prompt g_prompt;

QString settingsKey()
{
    return QStringLiteral("autosave/intervalMinutes");
}

Autosave::Choice askUser(QWidget *parent, const QString &projectFolder, const QDateTime &autosaved)
{
    QMessageBox box(QMessageBox::Question, Autosave::tr("Recover Unsaved Changes"),
                    Autosave::tr("LipSync Studio did not close normally while %1 had unsaved changes. "
                                 "An autosave from %2 is newer than the saved project.")
                        .arg(QDir::toNativeSeparators(projectFolder),
                             QLocale().toString(autosaved, QLocale::ShortFormat)),
                    QMessageBox::NoButton, parent);
    box.setInformativeText(Autosave::tr("Recover opens the autosaved version as unsaved changes; "
                                        "Discard deletes the autosave."));
    QPushButton *recover = box.addButton(Autosave::tr("Recover"), QMessageBox::AcceptRole);
    QPushButton *discard = box.addButton(QMessageBox::Discard);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(recover);
    box.exec();
    if (box.clickedButton() == recover)
        return Autosave::Choice::Recover;
    if (box.clickedButton() == discard)
        return Autosave::Choice::Discard;
    return Autosave::Choice::Cancel;
}

QString manifestIn(const QString &folder)
{
    return QDir(folder).filePath(QString::fromLatin1(Project::kManifestName));
}

} // namespace

void Autosave::setPrompt(Prompt prompt)
{
    g_prompt = std::move(prompt);
}

Autosave::Autosave(ProjectDocument *document, QWidget *window)
    : QObject(window), m_document(document)
{
    setIntervalMinutes(QSettings().value(settingsKey(), kDefaultIntervalMinutes).toDouble());
    connect(&m_timer, &QTimer::timeout, this, [this] { saveNow(); });
    connect(&m_write, &QFutureWatcher<QString>::finished, this, &Autosave::onWriteFinished);
    connect(document, &ProjectDocument::documentReset, this, &Autosave::onDocumentReset);
    // (A recovered document opens modified with its autosave in place: the next write replaces it.)
    connect(document, &ProjectDocument::sequenceChanged, this, [this] { m_changed = true; });
    connect(document, &ProjectDocument::modelsChanged, this, [this] { m_changed = true; });
    // Saved elsewhere: the old location's side copy is stale (a save in place calls discard).
    connect(document, &ProjectDocument::locationChanged, this, &Autosave::onDocumentReset);
}

Autosave::~Autosave()
{
    discard();
}

void Autosave::watch(TaskRunner *runner)
{
    connect(runner, &TaskRunner::taskFinished, this, [this](Task *task) {
        // After the commit: a finished tracking, alignment or training is worth keeping now.
        if (task->state() == Task::State::Finished && m_changed)
            QTimer::singleShot(0, this, [this] { saveNow(); });
    });
}

int Autosave::intervalMs() const
{
    return m_timer.isActive() ? m_timer.interval() : 0;
}

void Autosave::setIntervalMinutes(double minutes)
{
    if (minutes <= 0) {
        m_timer.stop();
        return;
    }
    m_timer.start(int(minutes * 60000));
}

QString Autosave::folderFor(const QString &projectFolder, bool readOnly)
{
    if (projectFolder.isEmpty())
        return {};
    if (!readOnly)
        return QDir(projectFolder).filePath(QStringLiteral(".autosave"));
    // Never write into the installation: one folder per read-only project in the app's data.
    const QByteArray key = QCryptographicHash::hash(QFileInfo(projectFolder).absoluteFilePath().toUtf8(),
                                                    QCryptographicHash::Sha1)
                               .toHex()
                               .left(16);
    return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation)
           + QStringLiteral("/autosave/") + QString::fromLatin1(key);
}

void Autosave::write(const Project &project, const QString &projectFolder, bool readOnly)
{
    const QString target = folderFor(projectFolder, readOnly);
    Project copy = project;
    copy.setFolder(projectFolder.toStdString()); // so save rebases relative paths into target
    copy.save(target.toStdString());
}

bool Autosave::saveNow()
{
    if (!m_document->isOpen() || m_target.isEmpty())
        return false;
    if (!m_document->isModified()) {
        // Undone back to the saved state: nothing unsaved to keep.
        if (!m_write.isRunning() && QFileInfo::exists(m_target))
            discard();
        m_changed = false;
        return false;
    }
    if (!m_changed && QFileInfo::exists(manifestIn(m_target)))
        return false;
    if (m_write.isRunning()) {
        m_pending = true;
        return true;
    }
    m_changed = false;
    m_writing = m_target;
    // The copy is cheap (the document's data, no media); serialising and fsyncing is not.
    // The write's result is the error message, empty on success. startFenced's hand-over also
    // orders setFuture's freeing of the previous write's result after that write's own.
    m_write.setFuture(startFenced<QString>(
        *QThreadPool::globalInstance(),
        [project = m_document->project(), folder = m_document->folder(), readOnly = m_document->isReadOnly()] {
            try {
                Autosave::write(project, folder, readOnly);
            } catch (const std::exception &e) {
                return QString::fromUtf8(e.what());
            }
            return QString();
        }));
    return true;
}

void Autosave::onWriteFinished()
{
    // Also reached from waitForWrite before the watcher's queued signal: handle each write once.
    if (m_writing.isEmpty() || !m_write.isFinished())
        return;
    handoffFence(); // after the write's own (startFenced)
    const QString error = m_write.result();
    const QString folder = std::exchange(m_writing, QString());
    if (!error.isEmpty()) {
        // Not a message box every few minutes (a read-only folder): the log and a signal.
        qWarning().noquote() << "autosave failed:" << error;
        emit failed(error);
    } else if (folder != m_target || !m_document->isModified()) {
        // Saved, undone or replaced while writing: the copy just written is stale.
        QDir(folder).removeRecursively();
    } else {
        emit written(folder);
    }
    if (std::exchange(m_pending, false))
        saveNow();
}

void Autosave::waitForWrite()
{
    while (!m_writing.isEmpty()) {
        m_write.waitForFinished();
        onWriteFinished();
    }
}

void Autosave::discard()
{
    m_write.waitForFinished();
    handoffFence(); // the finished write's result is freed with the watcher's future
    m_writing.clear();
    m_pending = false;
    if (!m_target.isEmpty())
        QDir(m_target).removeRecursively();
}

void Autosave::onDocumentReset()
{
    // Another document, or the same one in another place: an old location's autosave has served
    // its purpose — the user saved, discarded or recovered it. (A recovered document keeps its
    // location and with it the autosave until the next one replaces it.)
    const QString target = folderFor(m_document->folder(), m_document->isReadOnly());
    if (target != m_target)
        discard();
    m_target = target;
    m_changed = true;
}

Autosave::Offer Autosave::recoveryFor(const QString &projectFolder, bool readOnly, QWidget *parent)
{
    Offer offer;
    const QString target = folderFor(projectFolder, readOnly);
    const QFileInfo autosave(manifestIn(target));
    const QFileInfo saved(manifestIn(projectFolder));
    if (!autosave.isFile())
        return offer;
    if (saved.isFile() && autosave.lastModified() <= saved.lastModified()) {
        // Saved after this autosave was written: it holds nothing newer.
        QDir(target).removeRecursively();
        return offer;
    }
    if (!g_prompt && ErrorReporter::isBatchMode())
        return offer; // nobody to ask: open the saved project, keep the autosave
    offer.choice = (g_prompt ? g_prompt : askUser)(parent, projectFolder, autosave.lastModified());
    if (offer.choice == Choice::Discard)
        QDir(target).removeRecursively();
    if (offer.choice != Choice::Recover)
        return offer;
    try {
        Project project = Project::load(target.toStdString());
        // Its relative paths point from the autosave folder; the document lives in projectFolder.
        const std::string from = project.folder();
        for (Sequence &s : project.sequences)
            s.mediaFile = rebaseRelativePath(s.mediaFile, from, projectFolder.toStdString());
        for (ModelReference &m : project.models)
            m.file = rebaseRelativePath(m.file, from, projectFolder.toStdString());
        project.setFolder(projectFolder.toStdString());
        offer.recovered = std::move(project);
    } catch (const std::exception &e) {
        ErrorReporter::report(parent, tr("The autosaved changes could not be recovered; the saved project opens."),
                              e, autosave.filePath());
        offer.choice = Choice::Discard; // the saved project opens; the broken autosave stays for inspection
    }
    return offer;
}

} // namespace lipsync::studio
