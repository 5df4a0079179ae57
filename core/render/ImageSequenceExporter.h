#pragma once
// PNG image sequence export (lossless frames for editing tools): <folder>/<stem>00000.png, ...
//
// Atomic as a whole: the images are written into a hidden temporary folder beside `folder`
// (".<name>.part-XXXXXX")
// and moved into `folder` (created if missing) only when every frame is written. On cancel or
// error the temporary folder is removed and `folder` is left as it was.
#include <opencv2/core.hpp>

#include <functional>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;

// Writes frameAt(0..frameCount-1) and returns the paths written. Throws lipsync::Error naming
// the folder if it cannot be created or written, lipsync::Canceled on cancel.
// `compression` is PNG's zlib level 0..9 (speed versus size; the pixels are identical).
std::vector<std::string> exportImageSequence(const std::string &folder, int frameCount,
                                             const std::function<cv::Mat(int)> &frameAt,
                                             Feedback &feedback,
                                             const std::string &stem = "frame_",
                                             int compression = 3);

} // namespace lipsync
