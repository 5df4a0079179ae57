#include "eval/RealismMetrics.h"

#include "io/AudioDecoder.h"
#include "util/PhoneSet.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

constexpr double kNoMeasure = std::numeric_limits<double>::quiet_NaN();

Eigen::Vector2d point(const Eigen::VectorXd &shape, int i)
{
    return {shape[2 * i], shape[2 * i + 1]};
}

// Linear interpolation between order statistics of the finite values; NaN if there are none.
double percentile(std::vector<double> values, double p)
{
    values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
                 values.end());
    if (values.empty())
        return kNoMeasure;
    std::sort(values.begin(), values.end());
    const double x = p * double(values.size() - 1);
    const size_t i = size_t(std::floor(x));
    const size_t j = std::min(values.size() - 1, i + 1);
    return values[i] + (x - double(i)) * (values[j] - values[i]);
}

// Mean and s.d. (n denominator) of a and b over the frames where both are finite.
struct PairedMoments
{
    int n = 0;
    double meanA = 0, meanB = 0, varA = 0, varB = 0, cov = 0;
};

PairedMoments pairedMoments(const std::vector<double> &a, const std::vector<double> &b, int shift = 0)
{
    // Pairs (a[t + shift], b[t]).
    PairedMoments m;
    const int n = int(std::min(a.size(), b.size()));
    for (int t = 0; t < n; ++t) {
        const int u = t + shift;
        if (u < 0 || u >= int(a.size()) || !std::isfinite(a[size_t(u)]) || !std::isfinite(b[size_t(t)]))
            continue;
        ++m.n;
        m.meanA += a[size_t(u)];
        m.meanB += b[size_t(t)];
    }
    if (m.n == 0)
        return m;
    m.meanA /= m.n;
    m.meanB /= m.n;
    for (int t = 0; t < n; ++t) {
        const int u = t + shift;
        if (u < 0 || u >= int(a.size()) || !std::isfinite(a[size_t(u)]) || !std::isfinite(b[size_t(t)]))
            continue;
        const double da = a[size_t(u)] - m.meanA, db = b[size_t(t)] - m.meanB;
        m.varA += da * da;
        m.varB += db * db;
        m.cov += da * db;
    }
    m.varA /= m.n;
    m.varB /= m.n;
    m.cov /= m.n;
    return m;
}

// A variance that is only rounding error of a constant signal.
bool negligible(double variance, double mean)
{
    return !(variance > 1e-24 * std::max(1.0, mean * mean));
}

double correlation(const PairedMoments &m)
{
    if (m.n < 3 || negligible(m.varA, m.meanA) || negligible(m.varB, m.meanB))
        return kNoMeasure;
    return m.cov / std::sqrt(m.varA * m.varB);
}

} // namespace

double innerLipOpening(const Eigen::VectorXd &ibug68)
{
    if (ibug68.size() != 136)
        return kNoMeasure;
    const Eigen::Vector2d eyes = point(ibug68, 45) - point(ibug68, 36);
    const double interocular = eyes.norm();
    if (!(interocular > 0))
        return kNoMeasure;
    // The face's vertical: perpendicular to the eye line, pointing down the image.
    const Eigen::Vector2d down(-eyes.y() / interocular, eyes.x() / interocular);
    double sum = 0;
    for (const auto &[upper, lower] : {std::pair{61, 67}, std::pair{62, 66}, std::pair{63, 65}})
        sum += (point(ibug68, lower) - point(ibug68, upper)).dot(down);
    return std::max(0.0, sum / 3.0) / interocular;
}

cv::Rect2d mouthBox(const Eigen::VectorXd &ibug68, double margin)
{
    if (ibug68.size() != 136)
        return {};
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int i = 48; i < 68; ++i) {
        x0 = std::min(x0, ibug68[2 * i]);
        x1 = std::max(x1, ibug68[2 * i]);
        y0 = std::min(y0, ibug68[2 * i + 1]);
        y1 = std::max(y1, ibug68[2 * i + 1]);
    }
    const double w = x1 - x0, h = y1 - y0;
    return {x0 - margin * w, y0 - margin * h, (1 + 2 * margin) * w, (1 + 2 * margin) * h};
}

double pearsonOverFrames(const std::vector<double> &a, const std::vector<double> &b)
{
    return correlation(pairedMoments(a, b));
}

double articulationRatio(const std::vector<double> &generated, const std::vector<double> &recorded)
{
    const PairedMoments m = pairedMoments(generated, recorded);
    if (m.n < 2 || negligible(m.varB, m.meanB))
        return kNoMeasure;
    return std::sqrt(m.varA / m.varB);
}

double closedLevel(const std::vector<double> &recordedOpening, double tolerance)
{
    const double p10 = percentile(recordedOpening, 0.10);
    const double p90 = percentile(recordedOpening, 0.90);
    return p10 + tolerance * (p90 - p10);
}

std::vector<FrameRange> bilabialSegments(const Tier &phones, const FrameClock &clock, int margin)
{
    std::vector<FrameRange> out;
    const int frames = clock.count();
    for (const Interval &i : phones.intervals) {
        if (!PhoneSet::isBilabial(i.label) || frames == 0 || !(i.end > i.start))
            continue;
        if (i.end <= clock.startTime() + 1e-9 || i.start >= clock.endTime() - 1e-9)
            continue;
        // Frame t shows the interval [time(t), endTime(t)).
        const int first = std::max(0, clock.frameAt(i.start) - margin);
        const int last = std::min(frames - 1, clock.frameAt(i.end - 1e-9) + margin);
        if (last >= first)
            out.push_back({first, last});
    }
    return out;
}

int closedSegments(const std::vector<double> &opening, const std::vector<FrameRange> &segments,
                   double level)
{
    int closed = 0;
    for (const FrameRange &s : segments)
        for (int t = s.first; t <= s.last && t < int(opening.size()); ++t)
            if (std::isfinite(opening[size_t(t)]) && opening[size_t(t)] <= level) {
                ++closed;
                break;
            }
    return closed;
}

int closedInBoth(const std::vector<double> &generated, const std::vector<double> &recorded,
                 const std::vector<FrameRange> &segments, double level)
{
    int both = 0;
    for (const FrameRange &s : segments)
        both += closedSegments(generated, {s}, level) > 0 && closedSegments(recorded, {s}, level) > 0;
    return both;
}

FrameRange speechFrames(const Tier &phones, const FrameClock &frames)
{
    double first = INFINITY, last = -INFINITY;
    for (const Interval &i : phones.intervals)
        if (!PhoneSet::isSilence(i.label) && i.end > i.start) {
            first = std::min(first, i.start);
            last = std::max(last, i.end);
        }
    if (!(last > first) || frames.empty() || last <= frames.startTime() || first >= frames.endTime())
        return {0, -1};
    return {frames.frameAt(first), frames.frameAt(last - 1e-9)};
}

int closuresOutside(const std::vector<double> &opening, const std::vector<FrameRange> &segments,
                    const FrameRange &speech, double level)
{
    int runs = 0;
    const int last = std::min(speech.last, int(opening.size()) - 1);
    for (int t = std::max(0, speech.first); t <= last;) {
        const double o = opening[size_t(t)];
        if (!(std::isfinite(o) && o <= level)) {
            ++t;
            continue;
        }
        int end = t;
        while (end + 1 <= last && std::isfinite(opening[size_t(end + 1)]) && opening[size_t(end + 1)] <= level)
            ++end;
        bool bilabial = false;
        for (const FrameRange &s : segments)
            bilabial = bilabial || (s.first <= end && t <= s.last);
        runs += !bilabial;
        t = end + 1;
    }
    return runs;
}

std::vector<double> onlyWithin(std::vector<double> signal, const FrameRange &range)
{
    for (int t = 0; t < int(signal.size()); ++t)
        if (t < range.first || t > range.last)
            signal[size_t(t)] = std::numeric_limits<double>::quiet_NaN();
    return signal;
}

std::vector<double> audioEnergyPerFrame(const AudioBuffer &audio, const FrameClock &clock)
{
    const int frames = clock.count();
    std::vector<double> out(size_t(frames), kNoMeasure);
    if (audio.sampleRate <= 0 || !(clock.rate() > 0))
        return out;
    const double n = double(audio.samples.size());
    for (int t = 0; t < frames; ++t) {
        const double from = std::clamp((clock.time(t) - audio.startTime) * audio.sampleRate, 0.0, n);
        const double to = std::clamp((clock.endTime(t) - audio.startTime) * audio.sampleRate, 0.0, n);
        const size_t a = size_t(from), b = size_t(to);
        if (b <= a)
            continue;
        double sum = 0;
        for (size_t i = a; i < b; ++i)
            sum += double(audio.samples[i]) * audio.samples[i];
        out[size_t(t)] = 10.0 * std::log10(sum / double(b - a) + 1e-10);
    }
    return out;
}

double avLag(const std::vector<double> &opening, const std::vector<double> &energy, int maxLag)
{
    double best = -2.0, bestLag = kNoMeasure;
    for (int lag = -maxLag; lag <= maxLag; ++lag) {
        const double r = correlation(pairedMoments(opening, energy, lag));
        // Ties go to the smallest |lag| (the loop visits -L before L, so compare strictly).
        if (std::isfinite(r) && (r > best + 1e-12 || (std::abs(r - best) <= 1e-12 && std::abs(lag) < std::abs(bestLag)))) {
            best = r;
            bestLag = lag;
        }
    }
    return bestLag;
}

double gradientEnergy(const cv::Mat &bgr, const cv::Rect2d &box)
{
    const cv::Rect r = cv::Rect(cv::Rect2d(box)) & cv::Rect(0, 0, bgr.cols, bgr.rows);
    if (r.area() <= 0)
        return kNoMeasure;
    cv::Mat grey, laplacian;
    if (bgr.channels() == 3)
        cv::cvtColor(bgr(r), grey, cv::COLOR_BGR2GRAY);
    else
        grey = bgr(r);
    cv::Laplacian(grey, laplacian, CV_64F, 1, 1.0, 0.0, cv::BORDER_REPLICATE);
    return cv::mean(laplacian.mul(laplacian))[0];
}

SeamDeltaE seamDeltaE(const cv::Mat &frameIn, const cv::Mat &referenceIn, const cv::Mat &weightIn, int band)
{
    SeamDeltaE out;
    // Only the neighbourhood of the region matters.
    const cv::Rect region = cv::boundingRect(weightIn > 0);
    const int pad = band + 3;
    const cv::Rect roi = cv::Rect(region.x - pad, region.y - pad, region.width + 2 * pad, region.height + 2 * pad)
                         & cv::Rect(0, 0, weightIn.cols, weightIn.rows);
    const cv::Mat frame = frameIn(roi), reference = referenceIn(roi), weight = weightIn(roi);
    const cv::Mat full = weight == 255, touched = weight > 0;
    // Distances of untouched pixels to the region, and of fully synthesised pixels to its edge.
    cv::Mat outsideDistance, insideDistance;
    cv::distanceTransform(~touched, outsideDistance, cv::DIST_L2, cv::DIST_MASK_5);
    cv::distanceTransform(full, insideDistance, cv::DIST_L2, cv::DIST_MASK_5);
    const cv::Mat inner = full & (insideDistance <= band);
    const cv::Mat outer = ~touched & (outsideDistance <= band);
    if (cv::countNonZero(inner) == 0 || cv::countNonZero(outer) == 0) {
        out.frame = out.reference = kNoMeasure;
        return out;
    }
    // The nearest inner pixel of every pixel: labels of the zero pixels of ~inner, one per pixel.
    cv::Mat nearest, labels;
    cv::distanceTransform(~inner, nearest, labels, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
    std::vector<cv::Point> labelled(size_t(inner.total()) + 1);
    for (int y = 0; y < inner.rows; ++y)
        for (int x = 0; x < inner.cols; ++x)
            if (inner.at<uchar>(y, x))
                labelled[size_t(labels.at<int>(y, x))] = {x, y};
    auto lab = [](const cv::Mat &bgr) {
        cv::Mat f, l;
        bgr.convertTo(f, CV_32FC3, 1.0 / 255.0);
        cv::blur(f, f, cv::Size(3, 3));
        cv::cvtColor(f, l, cv::COLOR_BGR2Lab);
        return l;
    };
    const cv::Mat a = lab(frame), b = lab(reference);
    double sumA = 0, sumB = 0;
    for (int y = 0; y < outer.rows; ++y)
        for (int x = 0; x < outer.cols; ++x) {
            if (!outer.at<uchar>(y, x))
                continue;
            const cv::Point p = labelled[size_t(labels.at<int>(y, x))];
            sumA += cv::norm(a.at<cv::Vec3f>(y, x) - a.at<cv::Vec3f>(p));
            sumB += cv::norm(b.at<cv::Vec3f>(y, x) - b.at<cv::Vec3f>(p));
            ++out.pairs;
        }
    out.frame = sumA / out.pairs;
    out.reference = sumB / out.pairs;
    return out;
}

std::vector<double> naturalSeamDeltaE(const std::vector<double> &samePixels, const std::vector<double> &insideAsked,
                                      const std::vector<double> &trackedOpening, const std::vector<double> &ownEdge)
{
    std::vector<std::pair<double, double>> edges; // (opening, own edge) of the recording's open frames
    for (size_t t = 0; t < ownEdge.size(); ++t)
        if (std::isfinite(ownEdge[t]) && std::isfinite(trackedOpening[t]))
            edges.emplace_back(trackedOpening[t], ownEdge[t]);
    std::vector<double> out = samePixels;
    for (size_t t = 0; t < out.size(); ++t) {
        if (t >= insideAsked.size() || !std::isfinite(insideAsked[t]))
            continue;
        out[t] = kNoMeasure;
        if (edges.empty())
            continue;
        const double asked = insideAsked[t];
        const size_t k = std::min(kNaturalNeighbours, edges.size());
        std::partial_sort(edges.begin(), edges.begin() + std::ptrdiff_t(k), edges.end(),
                          [asked](const auto &a, const auto &b) {
                              return std::abs(a.first - asked) < std::abs(b.first - asked);
                          });
        double sum = 0;
        for (size_t i = 0; i < k; ++i)
            sum += edges[i].second;
        out[t] = sum / double(k);
    }
    return out;
}

} // namespace lipsync
