#pragma once
// FFTW's planner (plan creation and destruction) is not thread-safe; executing a plan on new
// arrays is. Every FFTW user in the audio module plans under this one lock.
#include <mutex>

namespace lipsync {

std::mutex &fftwPlannerMutex();

} // namespace lipsync
