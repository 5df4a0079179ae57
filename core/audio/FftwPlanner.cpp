#include "audio/FftwPlanner.h"

namespace lipsync {

std::mutex &fftwPlannerMutex()
{
    static std::mutex mutex;
    return mutex;
}

} // namespace lipsync
