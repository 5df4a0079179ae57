#include "io/AtomicFile.h"

#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#ifdef Q_OS_UNIX
#include <fcntl.h>
#include <unistd.h>
#endif

namespace lipsync {

namespace {

// QSaveFile fsyncs the data before the rename, but the rename lives in the folder's entry list:
// without this, a power cut shortly after a save can bring back the old file (or, on some file
// systems, an empty one). Best effort: not every file system supports syncing a directory.
void syncFolder(const QString &folder)
{
#ifdef Q_OS_UNIX
    const int fd = ::open(QFile::encodeName(folder).constData(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return;
    ::fsync(fd);
    ::close(fd);
#else
    Q_UNUSED(folder);
#endif
}

} // namespace

void writeFileAtomically(const std::string &path, const std::string &contents)
{
    const QString qpath = QString::fromStdString(path);
    QDir().mkpath(QFileInfo(qpath).absolutePath());
    QSaveFile file(qpath);
    if (!file.open(QIODevice::WriteOnly))
        throw Error("cannot write: " + file.errorString().toStdString(), path);
    if (file.write(contents.data(), qint64(contents.size())) != qint64(contents.size()))
        throw Error("write failed: " + file.errorString().toStdString(), path);
    if (!file.commit())
        throw Error("cannot save: " + file.errorString().toStdString(), path);
    syncFolder(QFileInfo(qpath).absolutePath());
}

std::string readWholeFile(const std::string &path)
{
    QFile file(QString::fromStdString(path));
    if (!file.exists())
        throw Error("no such file", path);
    if (!file.open(QIODevice::ReadOnly))
        throw Error("cannot read: " + file.errorString().toStdString(), path);
    const QByteArray data = file.readAll();
    return std::string(data.constData(), size_t(data.size()));
}

} // namespace lipsync
