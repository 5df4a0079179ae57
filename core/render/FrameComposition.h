#pragma once
// Frames laid out for comparison: real video beside generated faces (the paper's blind test shows
// two videos side by side), or several models in a grid. Panels are scaled to the height of the
// first panel (keeping their aspect ratio); an optional label is drawn in the top-left corner of
// each panel on a dark box so it stays legible on any face. BGR 8-bit in, BGR 8-bit out.
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace lipsync {

struct CompositionStyle
{
    int gap = 0;                           // pixels between panels
    cv::Scalar background{0, 0, 0};        // fills gaps and empty grid cells
    double labelScale = 0.5;               // cv::putText font scale (Hershey simplex: ASCII only)
};

// Two frames in one wide frame. Throws lipsync::Error if either frame is empty.
cv::Mat composeSideBySide(const cv::Mat &left, const cv::Mat &right,
                          const std::string &leftLabel = {}, const std::string &rightLabel = {},
                          const CompositionStyle &style = {});

// Panels row by row in `columns` columns (a last row may be incomplete). `labels` is empty or
// has one entry per panel (empty strings draw nothing). Throws lipsync::Error for no panels,
// an empty panel, columns < 1 or a labels list of the wrong length.
cv::Mat composeGrid(const std::vector<cv::Mat> &panels, int columns,
                    const std::vector<std::string> &labels = {}, const CompositionStyle &style = {});

} // namespace lipsync
