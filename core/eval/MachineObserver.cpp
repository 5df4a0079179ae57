#include "eval/MachineObserver.h"

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

constexpr int kCropWidth = 48, kCropHeight = 24;

const cv::HOGDescriptor &hog()
{
    static const cv::HOGDescriptor descriptor(cv::Size(kCropWidth, kCropHeight), cv::Size(16, 16), cv::Size(8, 8),
                                              cv::Size(8, 8), 9);
    return descriptor;
}

} // namespace

Eigen::VectorXf mouthAppearance(const cv::Mat &frame, const cv::Rect2d &mouth)
{
    const cv::Rect2d wide(mouth.x - 0.25 * mouth.width, mouth.y - 0.5 * mouth.height, 1.5 * mouth.width,
                          2.0 * mouth.height);
    const cv::Rect box = cv::Rect(wide) & cv::Rect(0, 0, frame.cols, frame.rows);
    cv::Mat crop;
    if (box.width < 2 || box.height < 2)
        crop = cv::Mat(kCropHeight, kCropWidth, CV_8UC3, cv::Scalar(0, 0, 0));
    else
        cv::resize(frame(box), crop, cv::Size(kCropWidth, kCropHeight), 0, 0, cv::INTER_AREA);
    cv::Mat grey;
    cv::cvtColor(crop, grey, cv::COLOR_BGR2GRAY);
    std::vector<float> hogValues;
    hog().compute(grey, hogValues);
    cv::Mat lab;
    crop.convertTo(lab, CV_32FC3, 1.0 / 255.0);
    cv::cvtColor(lab, lab, cv::COLOR_BGR2Lab);
    std::vector<float> colour;
    auto stats = [&](const cv::Mat &region) {
        cv::Scalar mean, sd;
        cv::meanStdDev(region, mean, sd);
        for (int c = 0; c < 3; ++c)
            colour.push_back(float(mean[c]));
        for (int c = 0; c < 3; ++c)
            colour.push_back(float(sd[c]));
    };
    stats(lab);
    for (int gy = 0; gy < 2; ++gy)
        for (int gx = 0; gx < 3; ++gx)
            stats(lab(cv::Rect(gx * kCropWidth / 3, gy * kCropHeight / 2, kCropWidth / 3, kCropHeight / 2)));
    Eigen::VectorXf out(Eigen::Index(hogValues.size() + colour.size()));
    std::copy(hogValues.begin(), hogValues.end(), out.data());
    std::copy(colour.begin(), colour.end(), out.data() + hogValues.size());
    return out;
}

void LinearObserver::fit(const Eigen::MatrixXf &real, const Eigen::MatrixXf &rendered, double ridge)
{
    const Eigen::Index n = real.rows() + rendered.rows(), d = real.cols();
    Eigen::MatrixXd x(n, d);
    x << real.cast<double>(), rendered.cast<double>();
    Eigen::VectorXd y(n);
    y << Eigen::VectorXd::Zero(real.rows()), Eigen::VectorXd::Ones(rendered.rows());
    m_mean = x.colwise().mean().transpose();
    m_scale = ((x.rowwise() - m_mean.transpose()).array().square().colwise().mean()).sqrt().max(1e-6).inverse().transpose();
    x = (x.rowwise() - m_mean.transpose()).array().rowwise() * m_scale.transpose().array();
    // Newton's method (iteratively reweighted least squares) on the bias and the weights.
    Eigen::MatrixXd a(n, d + 1);
    a << Eigen::VectorXd::Ones(n), x;
    Eigen::VectorXd beta = Eigen::VectorXd::Zero(d + 1);
    Eigen::VectorXd penalty = Eigen::VectorXd::Constant(d + 1, ridge);
    penalty[0] = 0.0; // the bias is not shrunk
    for (int iteration = 0; iteration < 25; ++iteration) {
        const Eigen::VectorXd p = ((-(a * beta)).array().exp() + 1.0).inverse().matrix();
        const Eigen::VectorXd w = (p.array() * (1.0 - p.array())).max(1e-9).matrix();
        Eigen::MatrixXd h = a.transpose() * w.asDiagonal() * a;
        h.diagonal() += penalty;
        const Eigen::VectorXd g = a.transpose() * (p - y) + penalty.cwiseProduct(beta);
        const Eigen::VectorXd step = h.ldlt().solve(g);
        if (!step.allFinite())
            break;
        beta -= step;
        if (step.norm() < 1e-6 * (1.0 + beta.norm()))
            break;
    }
    m_bias = beta[0];
    m_weights = beta.tail(d);
}

double LinearObserver::score(const Eigen::VectorXf &appearance) const
{
    if (m_weights.size() != appearance.size())
        return 0.0;
    const Eigen::VectorXd z = (appearance.cast<double>() - m_mean).cwiseProduct(m_scale);
    return m_bias + m_weights.dot(z);
}

std::vector<ObserverAccuracy> observeByFold(const std::vector<ObservedClip> &clips, int folds)
{
    std::vector<ObserverAccuracy> out(size_t(std::max(0, folds)));
    for (int f = 0; f < folds; ++f) {
        Eigen::Index realRows = 0, renderedRows = 0, d = 0;
        int tested = 0;
        for (const ObservedClip &c : clips) {
            if (c.fold == f) {
                ++tested;
                continue;
            }
            realRows += c.real.rows();
            renderedRows += c.rendered.rows();
            d = std::max(d, std::max(c.real.cols(), c.rendered.cols()));
        }
        if (tested == 0 || realRows == 0 || renderedRows == 0)
            continue;
        Eigen::MatrixXf real(realRows, d), rendered(renderedRows, d);
        Eigen::Index r = 0, g = 0;
        for (const ObservedClip &c : clips) {
            if (c.fold == f)
                continue;
            if (c.real.rows() > 0)
                real.middleRows(r, c.real.rows()) = c.real;
            if (c.rendered.rows() > 0)
                rendered.middleRows(g, c.rendered.rows()) = c.rendered;
            r += c.real.rows();
            g += c.rendered.rows();
        }
        LinearObserver observer;
        observer.fit(real, rendered);
        double rightFrames = 0, frames = 0, rightVideos = 0, videos = 0;
        // Frames judged rendered and frames seen: the recording's, then each kind of drawing.
        std::array<double, kFrameDrawings + 1> called{}, seen{};
        for (const ObservedClip &c : clips) {
            if (c.fold != f)
                continue;
            const bool split = c.drawing.size() == size_t(c.rendered.rows());
            auto judge = [&](const Eigen::MatrixXf &rows, bool isRendered) {
                if (rows.rows() == 0)
                    return;
                double sum = 0;
                for (Eigen::Index i = 0; i < rows.rows(); ++i) {
                    const double s = observer.score(rows.row(i).transpose());
                    sum += s;
                    rightFrames += (s > 0) == isRendered;
                    frames += 1;
                    if (!isRendered || split) {
                        const size_t k = isRendered ? 1 + size_t(c.drawing[size_t(i)]) : 0;
                        called[k] += s > 0;
                        seen[k] += 1;
                    }
                }
                rightVideos += (sum / double(rows.rows()) > 0) == isRendered;
                videos += 1;
            };
            judge(c.real, false);
            judge(c.rendered, true);
        }
        ObserverAccuracy &a = out[size_t(f)];
        if (frames > 0) {
            a.frames = rightFrames / frames;
            a.videos = rightVideos / videos;
        }
        auto share = [&](size_t k) { return seen[k] > 0 ? called[k] / seen[k] : ObserverAccuracy::kNone; };
        a.recordedJudgedRendered = share(0);
        for (size_t k = 0; k < a.drawnJudgedRendered.size(); ++k)
            a.drawnJudgedRendered[k] = share(k + 1);
    }
    return out;
}

} // namespace lipsync
