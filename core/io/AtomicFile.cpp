#include "io/AtomicFile.h"

#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

namespace lipsync {

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
