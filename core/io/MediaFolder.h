#pragma once
// The recordings of a folder, as every command that takes a folder of clips sees them (`project
// create`, `aligner train` / `adapt`, the folder forms of `align`, `track` and `landmarks
// detect`): each file whose extension is a media extension, hidden files left out, in name
// order, with the transcript of the same stem (the first of transcriptExtensions(), any case).
#include <string>
#include <vector>

namespace lipsync {

// Lower case with the dot: video containers first, then audio.
const std::vector<std::string> &mediaExtensions();
// "*.mpg, *.mp4, …" for messages.
std::string mediaExtensionList();

struct MediaFile
{
    std::string id;         // the file name without its extension
    std::string path;       // absolute
    std::string transcript; // absolute, or empty when there is none
};

// The media of `folder`, their transcripts looked up in `transcriptFolder` (empty: `folder`).
// Throws lipsync::Error naming the folder when it does not exist.
std::vector<MediaFile> listMediaFolder(const std::string &folder, const std::string &transcriptFolder = {});

} // namespace lipsync
