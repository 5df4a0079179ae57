#include "annotation/FrameClock.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

namespace {
// Times this close to an even grid are that grid: container time bases (1/90000, 1/12800,
// 1/30000) round frame times by far less.
constexpr double kEvenTolerance = 1e-4;
} // namespace

FrameClock FrameClock::uniform(double rate, int count, double firstTime)
{
    FrameClock c;
    c.m_count = std::max(0, count);
    c.m_rate = rate > 0 && std::isfinite(rate) ? rate : 0.0;
    c.m_first = std::isfinite(firstTime) ? firstTime : 0.0;
    return c;
}

FrameClock FrameClock::fromTimes(std::vector<double> times, double rate)
{
    const int n = int(times.size());
    if (!(rate > 0) || !std::isfinite(rate)) {
        // The median step: robust to the odd dropped frame.
        std::vector<double> steps;
        for (int i = 1; i < n; ++i)
            if (times[size_t(i)] > times[size_t(i - 1)])
                steps.push_back(times[size_t(i)] - times[size_t(i - 1)]);
        if (steps.empty())
            rate = 0.0;
        else {
            std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
            rate = 1.0 / steps[steps.size() / 2];
        }
    }
    if (n == 0)
        return uniform(rate, 0);
    bool even = rate > 0;
    for (int i = 0; even && i < n; ++i)
        even = std::abs(times[size_t(i)] - (times.front() + i / rate)) <= kEvenTolerance;
    if (even)
        return uniform(rate, n, times.front());
    // Decoders can repeat or reorder a timestamp; the clock keeps them increasing.
    for (int i = 1; i < n; ++i)
        times[size_t(i)] = std::max(times[size_t(i)], times[size_t(i - 1)] + 1e-6);
    FrameClock c;
    c.m_count = n;
    c.m_rate = rate;
    c.m_first = times.front();
    c.m_times = std::make_shared<const std::vector<double>>(std::move(times));
    return c;
}

double FrameClock::time(int i) const
{
    const double step = period();
    if (!m_times)
        return m_first + i * step;
    const std::vector<double> &t = *m_times;
    if (i < 0)
        return t.front() + i * step;
    if (i >= m_count)
        return t.back() + (i - (m_count - 1)) * step;
    return t[size_t(i)];
}

double FrameClock::endTime(int i) const
{
    if (m_times && i >= 0 && i + 1 < m_count)
        return (*m_times)[size_t(i + 1)];
    return time(i) + period();
}

int FrameClock::frameAt(double t) const
{
    if (m_count == 0)
        return -1;
    int i;
    if (!m_times) {
        i = m_rate > 0 ? int(std::floor((t - m_first) * m_rate + 1e-9)) : 0;
    } else {
        const std::vector<double> &times = *m_times;
        i = int(std::upper_bound(times.begin(), times.end(), t + 1e-9) - times.begin()) - 1;
    }
    return std::clamp(i, 0, m_count - 1);
}

int FrameClock::nearestFrame(double t) const
{
    const int i = frameAt(t);
    if (i < 0 || i + 1 >= m_count)
        return i;
    return t - time(i) <= time(i + 1) - t ? i : i + 1;
}

std::vector<double> FrameClock::times() const
{
    if (m_times)
        return *m_times;
    std::vector<double> t(static_cast<size_t>(m_count));
    for (int i = 0; i < m_count; ++i)
        t[size_t(i)] = time(i);
    return t;
}

FrameClock FrameClock::slice(int first, int n) const
{
    first = std::clamp(first, 0, m_count);
    n = std::clamp(n, 0, m_count - first);
    if (!m_times)
        return uniform(m_rate, n, time(first));
    return fromTimes(std::vector<double>(m_times->begin() + first, m_times->begin() + first + n), m_rate);
}

FrameClock FrameClock::shifted(double seconds) const
{
    FrameClock c = *this;
    c.m_first += seconds;
    if (m_times) {
        std::vector<double> t = *m_times;
        for (double &x : t)
            x += seconds;
        c.m_times = std::make_shared<const std::vector<double>>(std::move(t));
    }
    return c;
}

double FrameClock::boundaryAtOrBefore(double t) const
{
    if (m_count == 0)
        return t;
    if (t >= endTime() - 1e-6)
        return endTime();
    return time(frameAt(t + 1e-6));
}

double FrameClock::boundaryAtOrAfter(double t) const
{
    if (m_count == 0)
        return t;
    if (t <= startTime() + 1e-6)
        return startTime();
    const double before = boundaryAtOrBefore(t);
    if (before >= t - 1e-6)
        return before;
    return endTime(frameAt(t + 1e-6));
}

int FrameClock::frameAtBoundary(double t) const
{
    if (m_count == 0)
        return 0;
    if (t >= endTime() - 1e-6)
        return m_count;
    return nearestFrame(t);
}

bool FrameClock::operator==(const FrameClock &other) const
{
    if (m_count != other.m_count || m_rate != other.m_rate || isVariable() != other.isVariable())
        return false;
    return m_times ? *m_times == *other.m_times : m_first == other.m_first;
}

} // namespace lipsync
