#include "context/ErrorReporter.h"

#include "util/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QMessageBox>
#include <QtDebug>

namespace lipsync::studio {

namespace {
bool g_batch = false;
QString g_last;
} // namespace

void ErrorReporter::report(QWidget *parent, const QString &what, const QString &file, const QString &reason)
{
    QString text = what;
    if (!file.isEmpty())
        text += QStringLiteral("\n\n") + QCoreApplication::translate("ErrorReporter", "File: %1")
                                             .arg(QDir::toNativeSeparators(file));
    if (!reason.isEmpty())
        text += QStringLiteral("\n") + QCoreApplication::translate("ErrorReporter", "Reason: %1").arg(reason);
    g_last = text;
    if (g_batch) {
        qWarning().noquote() << text;
        return;
    }
    QMessageBox::warning(parent, QCoreApplication::translate("ErrorReporter", "LipSync Studio"), text);
}

void ErrorReporter::report(QWidget *parent, const QString &what, const std::exception &error,
                           const QString &fallbackFile)
{
    if (const auto *e = dynamic_cast<const Error *>(&error)) {
        QString reason = QString::fromStdString(e->reason());
        if (!e->field().empty())
            reason = QString::fromStdString(e->field()) + QStringLiteral(": ") + reason;
        const QString file = e->file().empty() ? fallbackFile : QString::fromStdString(e->file());
        report(parent, what, file, reason);
    } else {
        report(parent, what, fallbackFile, QString::fromUtf8(error.what()));
    }
}

void ErrorReporter::setBatchMode(bool batch)
{
    g_batch = batch;
}

bool ErrorReporter::isBatchMode()
{
    return g_batch;
}

QString ErrorReporter::lastMessage()
{
    return g_last;
}

} // namespace lipsync::studio
