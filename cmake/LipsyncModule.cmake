# lipsync_core_module(NAME [DEPS target...])
# Builds core/<NAME>/*.cpp into the static library lipsync_<NAME>. Sources are globbed so that
# modules can grow without touching shared build files; includes are relative to core/
# ("dynamics/DpdsModel.h").
function(lipsync_core_module name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS
       ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp ${CMAKE_CURRENT_SOURCE_DIR}/*.h)
  list(FILTER sources INCLUDE REGEX "\\.cpp$|\\.h$")
  set(cpp ${sources})
  list(FILTER cpp INCLUDE REGEX "\\.cpp$")
  if(NOT cpp)
    # A module whose sources have not been written yet is header-only.
    add_library(lipsync_${name} INTERFACE)
    target_include_directories(lipsync_${name} INTERFACE ${PROJECT_SOURCE_DIR}/core)
    target_link_libraries(lipsync_${name} INTERFACE ${ARG_DEPS})
  else()
    add_library(lipsync_${name} STATIC ${sources})
    target_include_directories(lipsync_${name} PUBLIC ${PROJECT_SOURCE_DIR}/core)
    target_link_libraries(lipsync_${name} PUBLIC ${ARG_DEPS})
    target_compile_options(lipsync_${name} PRIVATE -Wall -Wextra)
    set_target_properties(lipsync_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON
                          UNITY_BUILD ${LIPSYNC_UNITY} UNITY_BUILD_BATCH_SIZE 8)
    # A PCH pays for itself over many translation units; a unity build of a module has one per 8
    # sources, and under three of them parse the headers in less time than the PCH takes to build.
    list(LENGTH cpp count)
    set(units ${count})
    if(LIPSYNC_UNITY)
      math(EXPR units "(${count} + 7) / 8")
    endif()
    if(count GREATER_EQUAL 4 AND units GREATER_EQUAL 3 AND "Eigen3::Eigen" IN_LIST ARG_DEPS)
      lipsync_precompile(lipsync_${name})
    endif()
  endif()
  target_link_libraries(lipsync_core INTERFACE lipsync_${name})
endfunction()

set(LIPSYNC_TEST_DEFINITIONS
  LIPSYNC_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data"
  LIPSYNC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  LIPSYNC_BINARY_DIR="${PROJECT_BINARY_DIR}")

# lipsync_add_qtest(SOURCE [LIBS target...] [GUI])
# One QtTest executable per tst_*.cpp, registered with ctest under its path-derived name.
function(lipsync_add_qtest source)
  cmake_parse_arguments(ARG "GUI" "TIMEOUT" "LIBS" ${ARGN})
  get_filename_component(stem ${source} NAME_WE)
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR}/tests ${CMAKE_CURRENT_SOURCE_DIR}/${source})
  get_filename_component(reldir ${rel} DIRECTORY)
  string(REPLACE "/" "_" prefix "${reldir}")
  set(target "${prefix}_${stem}")
  add_executable(${target} ${source})
  target_link_libraries(${target} PRIVATE ${ARG_LIBS} Qt6::Test)
  # GCC 12 reports some `"literal" + std::string&&` (inlined C++20 constexpr std::string) as a
  # 2^63-byte memcpy, -Wstringop-overflow: a known false positive; tests build names that way.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-stringop-overflow)
  endif()
  target_compile_definitions(${target} PRIVATE ${LIPSYNC_TEST_DEFINITIONS})
  # The shared precompiled headers (cmake/PrecompiledHeaders.cmake), for tests of our libraries.
  if(ARG_GUI)
    lipsync_reuse_pch(${target} lipsync_test_pch_gui)
  elseif(ARG_LIBS MATCHES "lipsync_")
    lipsync_reuse_pch(${target} lipsync_test_pch)
  endif()
  # Every test includes its own .moc, so AUTOMOC's mocs_compilation.cpp is empty: no header to
  # load for it (about a second a test).
  set_source_files_properties(${CMAKE_CURRENT_BINARY_DIR}/${target}_autogen/mocs_compilation.cpp
                              TARGET_DIRECTORY ${target} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
  if(ARG_GUI)
    # Each GUI test on an X server of its own (tests/studio/with-own-display), so that they run
    # side by side and no other test's window takes the keyboard focus their shortcuts need. The
    # sanitizers' preload reaches the test only, not the wrapper's shell or Xvfb.
    set(preload "")
    if(LIPSYNC_SANITIZER_GUI_TEST_ENV)
      set(preload env ${LIPSYNC_SANITIZER_GUI_TEST_ENV})
    endif()
    add_test(NAME ${target} COMMAND ${PROJECT_SOURCE_DIR}/tests/studio/with-own-display
                                    ${preload} $<TARGET_FILE:${target}>)
  else()
    add_test(NAME ${target} COMMAND ${target})
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  if(LIPSYNC_SANITIZE)
    # Instrumented code runs 3-10 times slower: the end-to-end render tests take 40-110 s alone
    # under ASan + UBSan at -O1, and over 300 s with the whole suite sharing two cores.
    math(EXPR ARG_TIMEOUT "${ARG_TIMEOUT} * 3")
  endif()
  set_tests_properties(${target} PROPERTIES TIMEOUT ${ARG_TIMEOUT})
  if(LIPSYNC_SANITIZER_TEST_ENV)
    set_tests_properties(${target} PROPERTIES ENVIRONMENT "${LIPSYNC_SANITIZER_TEST_ENV}")
  endif()
  if(ARG_GUI)
    set_tests_properties(${target} PROPERTIES LABELS gui)
  endif()
endfunction()
