# `cmake --install` into a scratch prefix, then the installed `saltus` must run from there:
# every file in its usual place, and a model that exists only in the install tree is found
# (resources are looked up beside the executable, not in the source tree).
# Run as: cmake -DBUILD_DIR=... -DPREFIX=... -DGUI=ON|OFF -P install_test.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${status}")
endif()
set(expected bin/saltus share/applications/saltus.desktop
    share/icons/hicolor/scalable/apps/saltus.svg share/saltus/models/zatsiorsky-66kg.json
    share/saltus/examples/motions/M1-straight-back-somersault.motion.json)
if(GUI)
  list(APPEND expected bin/saltus-gui)
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
file(COPY_FILE "${PREFIX}/share/saltus/models/zatsiorsky-66kg.json"
     "${PREFIX}/share/saltus/models/install-only-model.json")
execute_process(
  COMMAND "${PREFIX}/bin/saltus" evaluate
          "${PREFIX}/share/saltus/examples/motions/M1-straight-back-somersault.motion.json"
          --model install-only-model --out "${PREFIX}/evaluate" --quiet
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "installed saltus failed (${status}): ${errors}")
endif()
if(NOT EXISTS "${PREFIX}/evaluate/result.json")
  message(FATAL_ERROR "installed saltus wrote no result")
endif()
