#pragma once
// The person's own mouths, for what moving the recording's lower face cannot give: lips closed
// where the recording holds them open (no warp brings apart lips together), and the inside of a
// mouth opened wider than recorded (the warp would stretch a thin dark line). The AAM can draw
// both, but its synthesis is an average over its training frames, sampled in a reference frame
// of at most 100 pixels: softer than any one of them, with the teeth of the open frames faintly
// in its closed lips (on HD footage the drawn lips read lighter and pinker than the person's own,
// and the teeth a smudge). Video Rewrite (Bregler, Covell & Slaney 1997) keeps to recorded mouths
// instead; so does this. Frames of the background video are kept (a mouth crop each, at the
// video's own resolution):
//  - closed: the frames whose tracked lips are closed, the most closed first; a closure is drawn
//    from the one nearest in time;
//  - open: a few frames for each band of opening (kOpenStep wide), those whose mouth moves between
//    its neighbouring frames as much as the video's open mouths typically do first (their median
//    motion): motion blurs lips and teeth, and a mouth stiller than the speech around it draws an
//    inside crisper than any the recording shows; an inside is drawn from the band of the
//    generated opening, so it changes only where the opening crosses a band's edge.
// Closed lips are moved onto the generated lips by the affine map that fits the ten mouth points
// best (least squares); an open mouth by the thin-plate spline through them, which puts its inner
// lips exactly on the generated ones. Never from within kAwaySeconds of the frame drawn into: the mouth comes from
// another moment of the footage, not from the recording's own beside it (which a realism report
// on that recording would otherwise be shown).
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

class VideoReader;

class MouthExemplars
{
public:
    // Lips this close count as closed: inner-lip gap over the mouth's width [choice: closed lips
    // as an AAM built from few frames fits them read 0.03-0.05 (HD weekly address), speech's open
    // mouths 0.1-0.3]. The most closed are kept first.
    static constexpr double kClosedShare = 0.05;
    // Recorded closures this far apart at least, the most closed first; so are the open mouths of
    // one band [choice].
    static constexpr double kSpacingSeconds = 0.2;
    static constexpr int kMaxExemplars = 32;
    // Open mouths: bands of this much opening share above kClosedShare, and this many kept per
    // band [choice: a band is a fifth of the span between a half-open /ae/ and a closure; three
    // let every frame find one at least kAwaySeconds away].
    static constexpr double kOpenStep = 0.025;
    static constexpr int kOpenPerBand = 3;
    // Openings beyond the mouth's width are misfits, not mouths: none is kept, so at most
    // kOpenPerBand x 38 open crops (and kMaxExemplars closed ones) are held, whatever the length.
    static constexpr double kMaxOpenShare = 1.0;
    // Never a mouth from within this time of the frame drawn into [choice: longer than a
    // bilabial closure and its neighbours' coarticulation].
    static constexpr double kAwaySeconds = 0.5;
    // The inner-lip gap of `shape` over its mouth's width: closed at kClosedShare or less.
    static double openingShare(const Eigen::VectorXd &shape);

    MouthExemplars() = default;
    // `shapes`: the 23 points fitted to each of the video's first shapes.rows() frames, in its
    // pixels; `usable[t]` false for frames whose fit is not to be trusted (no face, occluded).
    // Decodes the chosen frames (in order, so a long video is read forward once at most).
    MouthExemplars(VideoReader &video, const Eigen::MatrixXd &shapes, const std::vector<bool> &usable);

    bool empty() const { return m_exemplars.empty(); }
    // The recorded frames kept with closed lips, and with open mouths, in time order.
    std::vector<int> closedFrames() const;
    std::vector<int> openFrames() const;
    // The recorded frame of exemplar `which` (chooseClosed(), chooseOpen()), and its band of
    // opening (-1 for closed lips).
    int frame(int which) const { return m_exemplars.at(size_t(which)).frame; }
    int band(int which) const { return m_exemplars.at(size_t(which)).band; }
    // The band of opening of an opening share (kOpenStep wide above kClosedShare; 0 at or below).
    static int bandOf(double share);
    // The closed lips drawn at `time` (seconds on the video's clock): the nearest in time at
    // least kAwaySeconds away; -1 when there is none.
    int chooseClosed(double time) const;
    // The open mouth drawn at `time` for an opening share of `share`: of the nearest band that
    // has one at least kAwaySeconds away, the first kept; -1 when there is none.
    int chooseOpen(double time, double share) const;
    // Draws exemplar `which` (chooseClosed(), chooseOpen()) moved onto `generated` (23 points in
    // the frame's pixels) into `patch`, the frame's pixels of `box` (CV_8UC3, box.size()). False,
    // and nothing drawn, when the map would be degenerate (a scale outside a quarter to four times).
    bool draw(int which, const Eigen::VectorXd &generated, const cv::Rect &box, cv::Mat &patch) const;

private:
    struct Exemplar
    {
        int frame = 0;
        double time = 0.0;
        int band = -1;          // -1: closed; else the open band, (share - kClosedShare) / kOpenStep
        int order = 0;          // the order kept in (within a band: the least moving first)
        cv::Mat crop;           // the mouth and its surroundings, BGR
        cv::Point offset;       // the crop's top-left corner in the frame
        Eigen::VectorXd shape;  // the fitted 23 points, frame pixels
    };
    std::vector<Exemplar> m_exemplars; // in time order
};

} // namespace lipsync
