#pragma once
// Brand's fixed-lag streaming (docs/models.md §5): frame t leaves once label t + L is in, from the
// MLPG solve truncated there — the tridiagonal sweep for diagonal covariances, the block LDL^T
// sweep for full ones. FixedLagStreamers makes the streamers of one trained BrandModel at any
// lag; the streamers it makes share one copy of the model (they outlive a retrained model) and,
// with full covariances, each state's block terms, computed once when first needed. They are for
// one thread: the lag choice makes hundreds of them in turn, Live one per session.
#include "dynamics/StreamingGenerator.h"

#include <memory>

namespace lipsync {

class BrandModel;

class FixedLagStreamers
{
public:
    explicit FixedLagStreamers(const BrandModel &model);
    ~FixedLagStreamers();

    std::unique_ptr<StreamingGenerator> make(int lag) const;

    struct Shared; // what the streamers share (BrandStreamer.cpp)

private:
    std::shared_ptr<Shared> m_shared;
};

} // namespace lipsync
