# Runs tests/blender/test_addon.py in Debian's Blender, headless, on the controls and cues that
# `lipsync export` writes for a demo sequence (the .dat at Moho's 24 fps, the controls as CSV).
# -DBLENDER= Blender, -DLIPSYNC= the CLI, -DSOURCE_DIR= the source tree, -DWORK_DIR= a scratch folder.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(demo "${SOURCE_DIR}/resources/demo")
foreach(kind controls cues)
  if(kind STREQUAL "controls")
    set(out "${WORK_DIR}/bbaf2n-controls.csv")
  else()
    set(out "${WORK_DIR}/bbaf2n-cues.dat")
  endif()
  execute_process(COMMAND "${LIPSYNC}" export ${kind} --project "${demo}" --sequence bbaf2n --out "${out}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "lipsync export ${kind}: ${result}\n${output}\n${error}")
  endif()
endforeach()
execute_process(COMMAND "${BLENDER}" -b --factory-startup --python-exit-code 1
                        --python "${SOURCE_DIR}/tests/blender/test_addon.py" --
                        "${SOURCE_DIR}/resources/blender/lipsync_animation.py"
                        "${WORK_DIR}/bbaf2n-controls.csv" "${WORK_DIR}/bbaf2n-cues.dat"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error TIMEOUT 240)
message("${output}")
if(NOT result EQUAL 0 OR NOT output MATCHES "PASS: the add-on imported 75 frames")
  message(FATAL_ERROR "the Blender add-on test failed: ${result}\n${error}")
endif()
