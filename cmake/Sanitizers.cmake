# LIPSYNC_SANITIZE instruments every target of the tree (presets `asan` and `tsan`) and gives each
# ctest test the run-time options that make a finding fail the test:
#  - halt_on_error / -fno-sanitize-recover: the first report aborts the process, so UB is a failure
#    rather than a line in a log nobody reads;
#  - suppressions (tests/sanitizers/*.supp) hold only third-party noise — leaks and races inside
#    uninstrumented system libraries (Qt, fontconfig, Mesa, GStreamer) — each entry says why.
# The options reach child processes too (the CLI tests run the `lipsync` binary).
# TSan: ignore_noninstrumented_modules=1 makes TSan skip the memory accesses of libc calls made
# from uninstrumented libraries (Debian's Qt, GLib, Mesa, X11). Their own code is invisible to TSan
# anyway, and their locks are futexes it cannot see, so those accesses only ever produce reports
# about Qt's internals — e.g. the xcb platform's AT-SPI accessibility bridge starts QtDBus's
# "QDBusConnection" thread in every GUI test (Qt 6.4 has no switch to leave it out) and hands it
# strings and posted events. Every access made by lipsync code, and every lock, stays checked.
set(LIPSYNC_SANITIZER_TEST_ENV "")
set(LIPSYNC_SANITIZER_GUI_TEST_ENV "")
if(LIPSYNC_SANITIZE)
  set(supp ${PROJECT_SOURCE_DIR}/tests/sanitizers)
  set(flags -fsanitize=${LIPSYNC_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_compile_options(${flags})
  add_link_options(${flags})
  if(LIPSYNC_SANITIZE MATCHES "address")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1:suppressions=${supp}/asan.supp"
      "LSAN_OPTIONS=suppressions=${supp}/lsan.supp:print_suppressions=0")
  endif()
  # GUI tests: Mesa's software GL driver is dlopen'ed with the first GL context and dlclose'd at
  # exit, before LeakSanitizer reports — its process-lifetime allocations then show as
  # "<unknown module>", which no suppression can name. Preloading it keeps it mapped, so lsan.supp's
  # `leak:swrast_dri.so` matches them. gcc's ASan runtime is a shared library that has to come
  # first in the preload list; clang links its runtime into the executable, which comes first anyway.
  if(LIPSYNC_SANITIZE MATCHES "address")
    find_file(LIPSYNC_MESA_SWRAST swrast_dri.so PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri
              /usr/lib/dri NO_DEFAULT_PATH)
    set(preload ${LIPSYNC_MESA_SWRAST})
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                      OUTPUT_VARIABLE asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
      set(preload "${asan_runtime}:${LIPSYNC_MESA_SWRAST}")
    endif()
    if(LIPSYNC_MESA_SWRAST)
      set(LIPSYNC_SANITIZER_GUI_TEST_ENV "LD_PRELOAD=${preload}")
    endif()
  endif()
  if(LIPSYNC_SANITIZE MATCHES "undefined")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=${supp}/ubsan.supp")
  endif()
  if(LIPSYNC_SANITIZE MATCHES "thread")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:suppressions=${supp}/tsan.supp")
  endif()
endif()
