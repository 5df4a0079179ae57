#include "app/ScreenshotRunner.h"

#include "app/MainWindow.h"
#include "context/StudioContext.h"
#include "tasks/TaskRunner.h"

#include <QCoreApplication>
#include <QPixmap>
#include <QTimer>

#include <cstdio>

namespace lipsync::studio {

namespace {
constexpr int kTimeoutMs = 120000;
constexpr int kSettleMs = 300; // one more round of paints with the final data
} // namespace

ScreenshotRunner::ScreenshotRunner(MainWindow *window, QString file)
    : QObject(window), m_window(window), m_file(std::move(file))
{
}

void ScreenshotRunner::start()
{
    connect(m_window->context(), &StudioContext::sequenceLoadEnded, this, &ScreenshotRunner::waitForTasks);
    // Nothing loading (the project failed to open or has no sequences): shoot as it is.
    if (m_window->context()->taskRunner()->runningCount() == 0)
        QTimer::singleShot(0, this, &ScreenshotRunner::waitForTasks);
    // Never hang a headless run.
    QTimer::singleShot(kTimeoutMs, this, [] {
        std::fprintf(stderr, "%s\n",
                     qPrintable(tr("lipsync-studio: timed out waiting for the project to load")));
        QCoreApplication::exit(2);
    });
}

void ScreenshotRunner::waitForTasks()
{
    if (m_waiting)
        return;
    m_waiting = true;
    auto *poll = new QTimer(this);
    connect(poll, &QTimer::timeout, this, [this, poll] {
        if (m_window->context()->taskRunner()->runningCount() > 0)
            return;
        poll->stop();
        poll->deleteLater();
        QTimer::singleShot(kSettleMs, this, &ScreenshotRunner::shoot);
    });
    poll->start(50);
}

void ScreenshotRunner::shoot()
{
    if (!m_window->grab().save(m_file, "PNG")) {
        std::fprintf(stderr, "%s\n", qPrintable(tr("lipsync-studio: cannot write %1").arg(m_file)));
        QCoreApplication::exit(1);
        return;
    }
    QCoreApplication::exit(m_window->context()->media() ? 0 : 1);
}

} // namespace lipsync::studio
