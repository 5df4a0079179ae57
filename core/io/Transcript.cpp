#include "io/Transcript.h"

#include "io/AtomicFile.h"
#include "io/GridAlign.h"
#include "io/HtkLabel.h"
#include "io/Subtitles.h"
#include "io/TextGrid.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace lipsync {

namespace {

std::string extensionOf(const std::string &path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot);
    for (char &c : ext)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

Error unsupportedFormat(const std::string &ext, const std::string &path)
{
    return Error("unsupported transcript format '" + ext + "' (use .align, .lab, .txt, .TextGrid, .srt or .vtt)", path);
}

Transcript fromTier(const Tier &tier)
{
    Transcript t;
    t.timing = tier;
    t.timing.name = "words";
    for (const Interval &i : tier.intervals)
        if (!PhoneSet::isSilence(i.label))
            t.words.push_back(i.label);
    return t;
}

} // namespace

std::string Transcript::text() const
{
    std::string out;
    for (const std::string &w : words)
        out += (out.empty() ? "" : " ") + w;
    return out;
}

const std::vector<std::string> &transcriptExtensions()
{
    static const std::vector<std::string> list{".align", ".textgrid", ".lab", ".txt", ".srt", ".vtt"};
    return list;
}

Transcript parsePlainTranscript(const std::string &text)
{
    Transcript t;
    std::istringstream in(text);
    std::string word;
    while (in >> word)
        t.words.push_back(word);
    return t;
}

Transcript readTranscript(const std::string &path)
{
    const std::string ext = extensionOf(path);
    const std::vector<std::string> &known = transcriptExtensions();
    if (!ext.empty() && std::find(known.begin(), known.end(), ext) == known.end())
        throw unsupportedFormat(ext, path);
    return parseTranscript(readWholeFile(path), path);
}

Transcript parseTranscript(const std::string &bytes, const std::string &path)
{
    const std::string ext = extensionOf(path);
    Transcript t;
    if (ext == ".align") {
        t = fromTier(parseGridAlign(bytes, path));
    } else if (ext == ".textgrid") {
        const TextGrid grid = parseTextGrid(bytes, path);
        const Tier *words = grid.tier("words");
        for (const TextGridTier &candidate : grid.tiers)
            if (!words && !candidate.isPointTier)
                words = &candidate.tier;
        if (!words)
            throw Error("no interval tier with words", path);
        t = fromTier(*words);
    } else if (ext == ".lab") {
        // HTK timed labels, or (as MFA uses .lab) the plain transcript.
        std::istringstream first(bytes);
        std::string a, b;
        first >> a >> b;
        auto integer = [](const std::string &s) {
            return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
        };
        if (integer(a) && integer(b)) {
            Tier tier = parseHtkLabel(bytes, path);
            t = fromTier(tier);
        } else {
            t = parsePlainTranscript(bytes);
        }
    } else if (ext == ".txt" || ext.empty()) {
        t = parsePlainTranscript(bytes);
    } else if (ext == ".srt" || ext == ".vtt") {
        t.cues = parseSubtitles(bytes, ext == ".vtt" ? SubtitleFormat::WebVtt : SubtitleFormat::SubRip, path);
        for (const Interval &cue : t.cues.intervals)
            for (std::string &word : parsePlainTranscript(cue.label).words)
                t.words.push_back(std::move(word));
    } else {
        throw unsupportedFormat(ext, path);
    }
    if (t.words.empty())
        throw Error("the transcript has no words", path);
    return t;
}

void writePlainTranscript(const std::string &path, const Transcript &transcript)
{
    writeFileAtomically(path, transcript.text() + "\n");
}

} // namespace lipsync
