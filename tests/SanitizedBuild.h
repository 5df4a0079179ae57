#pragma once
// LIPSYNC_SANITIZED_BUILD: defined in sanitizer builds (ASan + UBSan: the asan and fuzz presets),
// which check memory, not speed, and run rendering and dlib several times slower. Tests that
// time or render a lot do less there.
#if defined(__SANITIZE_ADDRESS__)
#define LIPSYNC_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIPSYNC_SANITIZED_BUILD 1
#endif
#endif
