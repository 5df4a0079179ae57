#pragma once
// The per-sequence measures of the realism report (docs/models.md §6.5), on signals and images
// alone so each can be checked against known answers. Openings are per video frame; NaN marks a
// frame where no face was found, and every measure skips those frames.
//  - innerLipOpening: from dlib's 68 iBUG points (0-based), the mean distance between the inner
//    lips' upper and lower points (61/67, 62/66, 63/65) measured perpendicular to the line through
//    the outer eye corners (36, 45), divided by that corner distance, so head size and roll do not
//    matter.
//  - closedLevel: the opening at or below which the lips count as closed in a clip, from the
//    recording: its 10th percentile plus 40 % of its 10th-90th percentile spread. dlib's inner
//    lips at a /p b m/ closure in running speech stay 10-40 % of that spread above their level
//    at rest; 40 % agrees best with eye labels of closed and open lips (docs/closure-labels.tsv:
//    49 of 59 frames, against 42 at 30 %).
//  - bilabial segments: the /p b m/ intervals of the phone tier as video-frame ranges, widened by
//    a frame either way for the aligner's error (92 % of GRID boundaries within 40 ms); a segment
//    is closed when the opening reaches the closed level in one of its frames.
//  - avLag: the lag L in [-maxLag, maxLag] maximising the Pearson correlation of opening[t + L]
//    with the audio energy at frame t (positive: the lips follow the sound).
//  - gradientEnergy: mean squared Laplacian response of the grey image in a box (sharpness).
//  - seamDeltaE: mean CIE Lab ΔE (1976) across the edge of a synthesised region.
//  - speech frames: from the first to the last spoken (not silent) phone, the stretch where the
//    lips must follow the words, not the silence-speech-silence shape every clip shares.
//  - closures outside /p b m/: runs of closed frames (at or below the closed level) inside the
//    speech that touch no bilabial segment: lips shut where no /p b m/ asks for it.
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

struct AudioBuffer;

double innerLipOpening(const Eigen::VectorXd &ibug68);
// The bounding box of the 20 mouth points (48-67), grown by `margin` of its size on every side.
cv::Rect2d mouthBox(const Eigen::VectorXd &ibug68, double margin = 0.25);

// Pearson correlation over the frames where both are finite; NaN with fewer than 3 such frames
// or a constant signal.
double pearsonOverFrames(const std::vector<double> &a, const std::vector<double> &b);
// s.d.(generated) / s.d.(recorded) over the frames where both are finite; NaN if undefined.
double articulationRatio(const std::vector<double> &generated, const std::vector<double> &recorded);

double closedLevel(const std::vector<double> &recordedOpening, double tolerance = 0.4);

struct FrameRange
{
    int first = 0;
    int last = 0; // inclusive
};
// The /p b m/ (ARPAbet P, B, M) intervals of `phones` as the frames of `frames` they overlap,
// widened by `margin` frames either way, clipped to [0, frames.count()).
std::vector<FrameRange> bilabialSegments(const Tier &phones, const FrameClock &frames, int margin = 1);
// How many segments have a frame whose opening is at most `level` (frames without a face skipped).
int closedSegments(const std::vector<double> &opening, const std::vector<FrameRange> &segments,
                   double level);
// The segments closed in both openings.
int closedInBoth(const std::vector<double> &generated, const std::vector<double> &recorded,
                 const std::vector<FrameRange> &segments, double level);
// The frames of `frames` from the first to the last non-silent phone of `phones` (last < first:
// no speech).
FrameRange speechFrames(const Tier &phones, const FrameClock &frames);
// Runs of frames in `speech` with opening <= level that overlap none of `segments`.
int closuresOutside(const std::vector<double> &opening, const std::vector<FrameRange> &segments,
                    const FrameRange &speech, double level);
// `signal` with the frames outside `range` set to NaN.
std::vector<double> onlyWithin(std::vector<double> signal, const FrameRange &range);

// Log energy (dB) of the audio in each video frame's interval [time(t), endTime(t)).
std::vector<double> audioEnergyPerFrame(const AudioBuffer &audio, const FrameClock &frames);
// NaN when no lag has a defined correlation.
double avLag(const std::vector<double> &opening, const std::vector<double> &energy, int maxLag = 5);

// Mean squared 3x3 Laplacian of the grey image inside `box` (clipped to the image); NaN if empty.
double gradientEnergy(const cv::Mat &bgr, const cv::Rect2d &box);

struct SeamDeltaE
{
    double frame = 0.0;     // in the frame given (the composite)
    double reference = 0.0; // at the same pixel pairs in the reference frame (the recording)
    int pairs = 0;
};
// `weight`: the synthesised share of each pixel, 8-bit (255 fully synthesised, 0 untouched).
// Pairs every untouched pixel within `band` pixels outside the region with the nearest fully
// synthesised pixel within `band` pixels inside its (feathered) edge, and averages the ΔE of the
// pairs (colours smoothed over 3x3) in `frame` and in `reference`. NaN values without pairs.
SeamDeltaE seamDeltaE(const cv::Mat &frame, const cv::Mat &reference, const cv::Mat &weight,
                      int band = 3);

// The step a real edge shows where each frame's seam was measured (seamDeltaENatural): the
// recording at the same pixels (`samePixels`), except in frames where an inside was drawn
// (`insideAsked` finite: the inner-lip opening asked, pixels). There the same pixels of the
// recording hold its lips, closer together, with no edge between them; the real counterpart is the
// recording's own inner-lip edge (`ownEdge`, per frame) in the kNaturalNeighbours frames whose
// `trackedOpening` is nearest the one asked. NaN for such a frame when no frame has an own edge.
constexpr size_t kNaturalNeighbours = 5;
std::vector<double> naturalSeamDeltaE(const std::vector<double> &samePixels, const std::vector<double> &insideAsked,
                                      const std::vector<double> &trackedOpening, const std::vector<double> &ownEdge);

} // namespace lipsync
