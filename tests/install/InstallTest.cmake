# `cmake --install` gives a working CLI and studio: installs the build into a fresh prefix, then
# runs the installed `lipsync` (info on the installed demo, align with the installed aligner
# model) and the installed studio's --screenshot on the installed demo, with no build tree or
# source tree to fall back on. Run by ctest (tests/CMakeLists.txt) with -DBUILD_DIR= -DPREFIX=.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${error}")
endif()
set(ENV{LIPSYNC_RESOURCE_DIR} "")
set(ENV{LIPSYNC_ALIGNER_MODEL} "")
set(clip "${PREFIX}/share/lipsync/demo/media/bbaf2n.mpg")
foreach(file bin/lipsync share/lipsync/aligner/grid-s1.aligner share/lipsync/models/face_detection_yunet_2022mar.onnx
             share/lipsync/demo/project.json share/lipsync/blender/lipsync_animation.py)
  if(NOT EXISTS "${PREFIX}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()

execute_process(COMMAND "${PREFIX}/bin/lipsync" info "${clip}" --json
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT out MATCHES "\"frames\": *75")
  message(FATAL_ERROR "installed lipsync info: ${result}\n${out}\n${error}")
endif()

# The default aligner model is found at the prefix (no --model).
execute_process(COMMAND "${PREFIX}/bin/lipsync" align "${clip}"
                        --transcript "${PREFIX}/share/lipsync/demo/media/bbaf2n.align"
                        --out "${PREFIX}/bbaf2n.TextGrid" --json
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT EXISTS "${PREFIX}/bbaf2n.TextGrid")
  message(FATAL_ERROR "installed lipsync align: ${result}\n${out}\n${error}")
endif()

if(EXISTS "${PREFIX}/bin/lipsync-studio")
  execute_process(COMMAND "${PREFIX}/bin/lipsync-studio" --screenshot "${PREFIX}/studio.png"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE error TIMEOUT 120)
  file(SIZE "${PREFIX}/studio.png" bytes)
  if(NOT result EQUAL 0 OR bytes LESS 20000)
    message(FATAL_ERROR "installed lipsync-studio --screenshot: ${result} (${bytes} bytes)\n${out}\n${error}")
  endif()
endif()
file(REMOVE_RECURSE "${PREFIX}")
