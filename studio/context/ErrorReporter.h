#pragma once
// How the studio tells the user that something failed: a message box naming the file and the
// reason. In batch mode (--screenshot, tests) the message goes to the log instead, so nothing
// waits for a click.
#include <QString>

#include <exception>

class QWidget;

namespace lipsync::studio {

class ErrorReporter
{
public:
    static void report(QWidget *parent, const QString &what, const QString &file, const QString &reason);
    // Takes file and reason from a lipsync::Error; other exceptions give their what().
    static void report(QWidget *parent, const QString &what, const std::exception &error,
                       const QString &fallbackFile = {});

    static void setBatchMode(bool batch);
    static bool isBatchMode();
    // The last reported message (for tests and the screenshot mode's exit message).
    static QString lastMessage();
};

} // namespace lipsync::studio
