#pragma once
// --screenshot: waits until the window's project has loaded (first sequence's frame and
// waveform on screen, no background task left), grabs the window into a PNG and quits the
// application: exit code 0 if a sequence was shown, 1 if not (nothing loaded, or the file
// could not be written), 2 on a time-out.
#include <QObject>
#include <QString>

namespace lipsync::studio {

class MainWindow;

class ScreenshotRunner : public QObject
{
    Q_OBJECT
public:
    ScreenshotRunner(MainWindow *window, QString file);

    // Call after the project has been opened (or failed to open).
    void start();

private:
    void waitForTasks();
    void shoot();

    MainWindow *m_window;
    QString m_file;
    bool m_waiting = false;
};

} // namespace lipsync::studio
