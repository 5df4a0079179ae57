#include "render/FrameComposition.h"

#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lipsync {

namespace {

cv::Mat toBgr(const cv::Mat &frame)
{
    if (frame.channels() == 1) {
        cv::Mat bgr;
        cv::cvtColor(frame, bgr, cv::COLOR_GRAY2BGR);
        return bgr;
    }
    if (frame.channels() == 4) {
        cv::Mat bgr;
        cv::cvtColor(frame, bgr, cv::COLOR_BGRA2BGR);
        return bgr;
    }
    return frame;
}

void drawLabel(cv::Mat &panel, const std::string &label, double scale)
{
    if (label.empty())
        return;
    const int font = cv::FONT_HERSHEY_SIMPLEX;
    const int thickness = std::max(1, int(std::lround(scale * 2)));
    int baseline = 0;
    const cv::Size text = cv::getTextSize(label, font, scale, thickness, &baseline);
    const int margin = std::max(2, text.height / 3);
    const cv::Rect box = cv::Rect(0, 0, text.width + 2 * margin, text.height + baseline + 2 * margin)
                         & cv::Rect(0, 0, panel.cols, panel.rows);
    panel(box).setTo(cv::Scalar(0, 0, 0));
    cv::putText(panel, label, cv::Point(margin, margin + text.height), font, scale,
                cv::Scalar(255, 255, 255), thickness, cv::LINE_AA);
}

} // namespace

cv::Mat composeSideBySide(const cv::Mat &left, const cv::Mat &right, const std::string &leftLabel,
                          const std::string &rightLabel, const CompositionStyle &style)
{
    return composeGrid({left, right}, 2, {leftLabel, rightLabel}, style);
}

cv::Mat composeGrid(const std::vector<cv::Mat> &panels, int columns,
                    const std::vector<std::string> &labels, const CompositionStyle &style)
{
    if (panels.empty())
        throw Error("cannot compose frames: no panels");
    if (columns < 1)
        throw Error("cannot compose frames: at least one column is needed");
    if (!labels.empty() && labels.size() != panels.size())
        throw Error("cannot compose frames: " + std::to_string(labels.size()) + " labels for "
                    + std::to_string(panels.size()) + " panels");
    for (size_t i = 0; i < panels.size(); ++i)
        if (panels[i].empty() || panels[i].depth() != CV_8U)
            throw Error("cannot compose frames: panel " + std::to_string(i)
                        + " is empty or not 8-bit");

    // Every panel at the first panel's height; a column is as wide as its widest panel.
    const int height = panels[0].rows;
    columns = std::min(columns, int(panels.size()));
    const int rows = (int(panels.size()) + columns - 1) / columns;
    std::vector<cv::Mat> scaled;
    std::vector<int> columnWidth(static_cast<size_t>(columns), 0);
    for (size_t i = 0; i < panels.size(); ++i) {
        cv::Mat panel = toBgr(panels[i]);
        if (panel.rows != height) {
            const int width = std::max(1, int(std::lround(double(panel.cols) * height / panel.rows)));
            cv::resize(panel, panel, cv::Size(width, height), 0, 0, cv::INTER_AREA);
        } else {
            panel = panel.clone();
        }
        if (!labels.empty())
            drawLabel(panel, labels[i], style.labelScale);
        int &w = columnWidth[i % size_t(columns)];
        w = std::max(w, panel.cols);
        scaled.push_back(panel);
    }
    int width = style.gap * (columns - 1);
    for (int w : columnWidth)
        width += w;
    cv::Mat out(rows * height + style.gap * (rows - 1), width, CV_8UC3, style.background);
    for (size_t i = 0; i < scaled.size(); ++i) {
        const int row = int(i) / columns;
        const int column = int(i) % columns;
        int x = column * style.gap;
        for (int c = 0; c < column; ++c)
            x += columnWidth[size_t(c)];
        scaled[i].copyTo(out(cv::Rect(x, row * (height + style.gap), scaled[i].cols, height)));
    }
    return out;
}

} // namespace lipsync
