#pragma once
// Progress and cancellation for long algorithms (AAM building, tracking, alignment, training,
// export). Algorithms take a Feedback& and know nothing about threads: they report a fraction,
// an optional per-iteration objective (for live plots) and poll isCanceled() at loop heads.
// The design follows QGIS's QgsFeedback and Ceres' IterationCallback.
#include <atomic>
#include <functional>
#include <mutex>
#include <string>

namespace lipsync {

// Thrown by Feedback::throwIfCanceled(); TaskRunner treats it as a clean cancel.
class Canceled : public std::exception
{
public:
    const char *what() const noexcept override { return "canceled"; }
};

class Feedback
{
public:
    Feedback() = default;
    // A child reporting into [from, to] of the parent's range and sharing its cancel flag. Its
    // status reaches the parent too; its iterations do not: they belong to a sub-problem with an
    // objective of its own (SLDS's DPDS initialisation plotted as SLDS iterations 1..30, then SLDS's
    // own 1..200, drew a line back across the studio's objective plot).
    Feedback(Feedback &parent, double from, double to);
    Feedback(const Feedback &) = delete;
    // The feedback of a call nobody watches or cancels (the default of functions that take one):
    // one per thread, so that its progress is nobody's. Never cancel it.
    static Feedback &none();
    Feedback &operator=(const Feedback &) = delete;
    virtual ~Feedback() = default;

    // fraction in [0, 1] of this feedback's range. Thread-safe.
    void setProgress(double fraction);
    double progress() const { return m_progress.load(); }

    void setStatus(const std::string &status);
    std::string status() const;

    // One optimisation iteration finished with the given objective (log-likelihood, error...).
    void reportIteration(int iteration, double objective);

    void cancel();
    bool isCanceled() const;
    void throwIfCanceled() const
    {
        if (isCanceled())
            throw Canceled();
    }

    // Observers, called on the reporting (worker) thread. Set before the work starts.
    std::function<void(double)> onProgress;
    std::function<void(const std::string &)> onStatus;
    std::function<void(int, double)> onIteration;

private:
    Feedback *m_parent = nullptr;
    double m_from = 0.0;
    double m_to = 1.0;
    std::atomic<double> m_progress{0.0};
    std::atomic<bool> m_canceled{false};
    mutable std::mutex m_statusMutex;
    std::string m_status;
};

} // namespace lipsync
