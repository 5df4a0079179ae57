#pragma once
// The person's own closed lips, for a render that closes a mouth the recording holds open. No
// warp brings apart lips together (FaceRenderer draws them), and the AAM's synthesis of closed
// lips is an average over its training frames: softer than any one of them, and with the teeth
// and the mouth's inside of the open frames faintly in it (on HD footage the drawn lips read
// lighter and pinker than the person's own). Video Rewrite (Bregler, Covell & Slaney 1997) keeps
// to recorded mouths instead; so does this: the frames of the background video whose tracked lips
// are closed are kept (a mouth crop each), and a closure is drawn from the one nearest in time,
// moved onto the generated lips by the affine map that fits the ten mouth points best (least
// squares). Never from within kAwaySeconds of the frame drawn into: the lips come from another
// moment of the footage, not from the recording's own closure beside it (which a realism report
// on that recording would otherwise be shown).
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

class VideoReader;

class ClosedLipExemplars
{
public:
    // Lips this close count as closed: inner-lip gap over the mouth's width [choice: closed lips
    // as an AAM built from few frames fits them read 0.03-0.05 (HD weekly address), speech's open
    // mouths 0.1-0.3]. The most closed are kept first.
    static constexpr double kClosedShare = 0.05;
    // Recorded closures this far apart at least, the most closed first [choice].
    static constexpr double kSpacingSeconds = 0.2;
    static constexpr int kMaxExemplars = 32;
    // Never a closure from within this time of the frame drawn into [choice: longer than a
    // bilabial closure and its neighbours' coarticulation].
    static constexpr double kAwaySeconds = 0.5;
    // The inner-lip gap of `shape` over its mouth's width: closed at kClosedShare or less.
    static double openingShare(const Eigen::VectorXd &shape);

    ClosedLipExemplars() = default;
    // `shapes`: the 23 points fitted to each of the video's first shapes.rows() frames, in its
    // pixels; `usable[t]` false for frames whose fit is not to be trusted (no face, occluded).
    // Decodes the chosen frames (in order, so a long video is read forward once at most).
    ClosedLipExemplars(VideoReader &video, const Eigen::MatrixXd &shapes, const std::vector<bool> &usable);

    bool empty() const { return m_exemplars.empty(); }
    // The recorded frames kept, in time order.
    std::vector<int> frames() const;
    // The exemplar drawn at `time` (seconds on the video's clock): the nearest in time at least
    // kAwaySeconds away; -1 when there is none.
    int choose(double time) const;
    // Draws exemplar `which` (choose()) moved onto `generated` (23 points in the frame's pixels)
    // into `patch`, the frame's pixels of `box` (CV_8UC3, box.size()). False, and nothing drawn,
    // when the map would be degenerate (a scale outside a quarter to four times).
    bool draw(int which, const Eigen::VectorXd &generated, const cv::Rect &box, cv::Mat &patch) const;

private:
    struct Exemplar
    {
        int frame = 0;
        double time = 0.0;
        cv::Mat crop;           // the mouth and its surroundings, BGR
        cv::Point offset;       // the crop's top-left corner in the frame
        Eigen::VectorXd shape;  // the fitted 23 points, frame pixels
    };
    std::vector<Exemplar> m_exemplars;
};

} // namespace lipsync
