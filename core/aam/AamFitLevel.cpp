#include "aam/AamFitLevel.h"

#include <opencv2/core.hpp>

namespace lipsync {

Eigen::MatrixXf steepestDescent(const AamFitLevel &level, const PiecewiseAffineWarp &warp,
                                const Eigen::VectorXf &texture)
{
    // Texture gradient by central differences inside the frame (one-sided at its edge), per
    // channel; the channels' rows are stacked.
    const int N = warp.pixelCount();
    const int channels = int(texture.size() / N);
    const cv::Mat &index = warp.indexMap();
    Eigen::MatrixXf sd(texture.size(), level.warpX.cols());
    for (int c = 0; c < channels; ++c) {
        const float *t = texture.data() + size_t(c) * size_t(N);
        auto valueAt = [&](int x, int y, float &v) {
            if (x < 0 || y < 0 || x >= index.cols || y >= index.rows)
                return false;
            const int j = index.at<int>(y, x);
            if (j < 0)
                return false;
            v = t[j];
            return true;
        };
        Eigen::VectorXf gx(N), gy(N);
        for (int i = 0; i < N; ++i) {
            const int x = warp.pixelX(i), y = warp.pixelY(i);
            const float v0 = t[i];
            float a = 0, b = 0;
            const bool l = valueAt(x - 1, y, a), r = valueAt(x + 1, y, b);
            gx[i] = l && r ? 0.5f * (b - a) : r ? b - v0 : l ? v0 - a : 0.f;
            const bool u = valueAt(x, y - 1, a), d = valueAt(x, y + 1, b);
            gy[i] = u && d ? 0.5f * (b - a) : d ? b - v0 : u ? v0 - a : 0.f;
        }
        sd.middleRows(Eigen::Index(c) * N, N) = gx.asDiagonal() * level.warpX + gy.asDiagonal() * level.warpY;
    }
    // Project out the appearance variation.
    if (level.appearance.cols() > 0)
        sd -= level.appearance * (level.appearance.transpose() * sd);
    return sd;
}

} // namespace lipsync
