#pragma once
// Damaged inputs made from repo data, for the bad-input tests of the CLI and the studio: a copy
// read whole, written (folders created), or with bytes inverted.
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>

namespace lipsync::testing {

inline QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline bool writeAll(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// Every 97th byte of the middle half inverted: the header survives, the content does not.
inline QByteArray flipped(QByteArray bytes)
{
    for (qsizetype i = bytes.size() / 4; i < 3 * bytes.size() / 4; i += 97)
        bytes[i] = char(~bytes[i]);
    return bytes;
}

} // namespace lipsync::testing
