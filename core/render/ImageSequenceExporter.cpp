#include "render/ImageSequenceExporter.h"

#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgcodecs.hpp>

#include <stdlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace lipsync {

namespace fs = std::filesystem;

namespace {

// Removes the temporary folder unless released (the RAII half of the atomic export).
struct TemporaryFolder
{
    std::string path;
    ~TemporaryFolder()
    {
        if (!path.empty()) {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    }
};

std::string frameName(const std::string &stem, int index)
{
    char number[16];
    std::snprintf(number, sizeof number, "%05d", index);
    return stem + number + ".png";
}

} // namespace

std::vector<std::string> exportImageSequence(const std::string &folder, int frameCount,
                                             const std::function<cv::Mat(int)> &frameAt,
                                             Feedback &feedback, const std::string &stem,
                                             int compression)
{
    if (frameCount <= 0)
        throw Error("cannot write images: no frames to export", folder);
    if (stem.find('/') != std::string::npos)
        throw Error("cannot write images: the file name stem contains '/'", folder);
    fs::path target = fs::path(folder).lexically_normal();
    if (target.filename().empty())
        target = target.parent_path();
    fs::path parent = target.parent_path();
    if (parent.empty())
        parent = ".";
    std::error_code ec;
    if (!fs::is_directory(parent, ec))
        throw Error("cannot write images: the folder " + parent.string() + " does not exist", folder);
    if (fs::exists(target, ec) && !fs::is_directory(target, ec))
        throw Error("cannot write images: the path exists and is not a folder", folder);

    std::string hidden(1, '.');
    hidden.append(target.filename().string()).append(".part-XXXXXX"); // mkdtemp: X's last
    std::string pattern = (parent / hidden).string();
    if (!mkdtemp(pattern.data()))
        throw Error(std::string("cannot write images: ") + std::strerror(errno), folder);
    TemporaryFolder temporary{pattern};

    feedback.setStatus("Exporting images to " + folder);
    const std::vector<int> options{cv::IMWRITE_PNG_COMPRESSION, compression};
    std::vector<std::string> names;
    for (int i = 0; i < frameCount; ++i) {
        feedback.throwIfCanceled();
        const cv::Mat frame = frameAt(i);
        const std::string name = frameName(stem, i);
        bool written = false;
        try {
            written = !frame.empty() && cv::imwrite((fs::path(pattern) / name).string(), frame, options);
        } catch (const cv::Exception &e) {
            throw Error("cannot write image " + name + ": " + e.what(), folder);
        }
        if (!written)
            throw Error("cannot write image " + name + " (empty frame or disk full?)", folder);
        names.push_back(name);
        feedback.setProgress(0.95 * (i + 1) / frameCount);
    }
    feedback.throwIfCanceled();

    // Every frame is on disk: move them into place (same file system, so renames).
    fs::create_directories(target, ec);
    if (ec)
        throw Error("cannot create the folder: " + ec.message(), folder);
    std::vector<std::string> paths;
    for (const std::string &name : names) {
        const fs::path destination = target / name;
        fs::rename(fs::path(pattern) / name, destination, ec);
        if (ec)
            throw Error("cannot write image " + name + ": " + ec.message(), folder);
        paths.push_back(destination.string());
    }
    feedback.setProgress(1.0);
    return paths;
}

} // namespace lipsync
