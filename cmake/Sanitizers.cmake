# LIPSYNC_SANITIZE instruments every target of the tree (presets `asan` and `tsan`) and gives each
# ctest test the run-time options that make a finding fail the test:
#  - halt_on_error / -fno-sanitize-recover: the first report aborts the process, so UB is a failure
#    rather than a line in a log nobody reads;
#  - suppressions (tests/sanitizers/*.supp) hold only third-party noise — leaks and races inside
#    uninstrumented system libraries (Qt, fontconfig, Mesa, GStreamer) — each entry says why.
# The options reach child processes too (the CLI tests run the `lipsync` binary).
set(LIPSYNC_SANITIZER_TEST_ENV "")
if(LIPSYNC_SANITIZE)
  set(supp ${PROJECT_SOURCE_DIR}/tests/sanitizers)
  set(flags -fsanitize=${LIPSYNC_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_compile_options(${flags})
  add_link_options(${flags})
  if(LIPSYNC_SANITIZE MATCHES "address")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1"
      "LSAN_OPTIONS=suppressions=${supp}/lsan.supp:print_suppressions=0")
  endif()
  if(LIPSYNC_SANITIZE MATCHES "undefined")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=${supp}/ubsan.supp")
  endif()
  if(LIPSYNC_SANITIZE MATCHES "thread")
    list(APPEND LIPSYNC_SANITIZER_TEST_ENV
      "TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=${supp}/tsan.supp")
  endif()
endif()
