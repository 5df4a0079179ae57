// One libFuzzer target per parser: compiled once per parser in fuzz/CMakeLists.txt with
// LIPSYNC_FUZZ_FUNCTION naming its function from FuzzParsers.h. lipsync::Error is the parser's clean
// answer to bad input and is swallowed; any other exception escapes and libFuzzer reports it as a
// crash, as it does a sanitizer finding, a timeout or an allocation over -malloc_limit_mb.
#include "FuzzParsers.h"

#include "util/Error.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    try {
        lipsync::fuzz::LIPSYNC_FUZZ_FUNCTION(std::string(reinterpret_cast<const char *>(data), size));
    } catch (const lipsync::Error &) {
    }
    return 0;
}
