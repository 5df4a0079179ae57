#pragma once
// Frame-by-frame generation (docs/models.md §5): labels go in one at a time, frames come out once
// the model's look-ahead allows. Zero-latency models (HMM-mean, SLDS, DPDS) emit one frame per
// label; fixed-lag Brand emits frame t once label t+L is known, and the rest on finish().
#include <Eigen/Core>

#include <deque>

namespace lipsync {

// The frames a streamer has made ready and not yet handed out, oldest first (for streamers that
// make several frames ready at once).
class ReadyFrames
{
public:
    void push(const Eigen::VectorXd &frame) { m_frames.push_back(frame); }
    bool pop(Eigen::Ref<Eigen::VectorXd> frame)
    {
        if (m_frames.empty())
            return false;
        frame = m_frames.front();
        m_frames.pop_front();
        return true;
    }

private:
    std::deque<Eigen::VectorXd> m_frames;
};

class StreamingGenerator
{
public:
    virtual ~StreamingGenerator() = default;
    // Frames of look-ahead: a frame is ready latency() labels after its own.
    virtual int latency() const = 0;
    // Feeds the label of the next frame (throws lipsync::Error for a label outside 0..P-1).
    virtual void push(int label) = 0;
    // No more labels: every remaining frame becomes ready.
    virtual void finish() = 0;
    // Copies the next ready frame (d values) into `frame` and returns true, or returns false.
    virtual bool pop(Eigen::Ref<Eigen::VectorXd> frame) = 0;
};

} // namespace lipsync
