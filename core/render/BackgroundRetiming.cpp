#include "render/BackgroundRetiming.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

double poseStep(const Similarity &a, const Similarity &b)
{
    const double sa = std::max(1e-9, a.scale()), sb = std::max(1e-9, b.scale());
    const double move = std::hypot(a.tx - b.tx, a.ty - b.ty) / (0.5 * (sa + sb));
    const double zoom = std::log(sa / sb);
    double turn = std::atan2(a.b, a.a) - std::atan2(b.b, b.a);
    turn = std::remainder(turn, 2.0 * M_PI);
    return std::sqrt(move * move + zoom * zoom + turn * turn);
}

BackgroundRetiming retimeBackground(const std::vector<Similarity> &poses, int frames,
                                    const BackgroundRetimingOptions &options)
{
    BackgroundRetiming out;
    const int n = int(poses.size());
    if (n == 0 || frames <= 0)
        return out;
    std::vector<double> steps;
    for (int i = 0; i + 1 < n; ++i)
        steps.push_back(poseStep(poses[size_t(i)], poses[size_t(i + 1)]));
    if (!steps.empty()) {
        std::vector<double> sorted = steps;
        const size_t k = std::min(sorted.size() - 1, size_t(std::floor(0.99 * double(sorted.size() - 1) + 0.5)));
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
        out.naturalStep99 = sorted[k];
    }
    const int run = std::max(1, options.shortestRun);
    int pos = 0, direction = 1;
    int cutFrom = -1, cutTo = -1; // the planned cut of the current forward run
    out.frames.reserve(size_t(frames));
    while (int(out.frames.size()) < frames) {
        out.frames.push_back(pos);
        if (n == 1)
            continue;
        if (direction > 0) {
            if (pos == cutFrom) {
                out.cuts.push_back(int(out.frames.size()));
                out.cutSteps.push_back(poseStep(poses[size_t(pos)], poses[size_t(cutTo)]));
                pos = cutTo;
                cutFrom = cutTo = -1;
                continue;
            }
            if (cutFrom < 0 && n - 1 - pos <= options.searchWindow) {
                // Plan this run's cut: from a frame i of the window to an earlier frame j with a
                // full run after it, the smallest pose step.
                double best = std::numeric_limits<double>::infinity();
                for (int i = pos; i < n; ++i)
                    for (int j = 0; j + run < n; ++j) {
                        if (std::abs(j - i) <= run)
                            continue;
                        const double step = poseStep(poses[size_t(i)], poses[size_t(j)]);
                        if (step < best) {
                            best = step;
                            cutFrom = i;
                            cutTo = j;
                        }
                    }
                if (!(best <= out.naturalStep99))
                    cutFrom = cutTo = n; // none small enough: turn back at the end
                if (cutFrom == pos && cutTo < n) {
                    out.cuts.push_back(int(out.frames.size()));
                    out.cutSteps.push_back(best);
                    pos = cutTo;
                    cutFrom = cutTo = -1;
                    continue;
                }
            }
            if (pos + 1 < n) {
                ++pos;
            } else {
                ++out.reversals;
                direction = -1;
                cutFrom = cutTo = -1;
                --pos;
            }
        } else {
            if (pos > 0) {
                --pos;
            } else {
                direction = 1;
                ++pos;
            }
        }
    }
    for (size_t k = 0; k + 1 < out.frames.size(); ++k)
        out.largestStep = std::max(out.largestStep, poseStep(poses[size_t(out.frames[k])], poses[size_t(out.frames[k + 1])]));
    return out;
}

} // namespace lipsync
