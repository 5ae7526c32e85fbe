# Checks that tests/unit mirrors src/saltus (tests/README.md): every tests/unit/<path>_test.cpp
# names a library file src/saltus/<path>.{h,cpp}, and every library file has such a test unless
# it is listed below with the test that covers it. A file <name>_impl.h belongs to <name>.
# Run as: cmake -DSOURCE_DIR=src/saltus -DTEST_DIR=tests/unit -P mirror_sources.cmake

# Library files without a test of their own: "<layer>/<file>=<why, and where it is tested>".
set(covered_elsewhere
    "dynamics/body_state=a plain struct, read and written by every dynamics test"
    "motion/motion=plain structs, read and written in unit/formats/motion_file_test.cpp"
    "optim/nlp=the interface, whose implementations are tested (unit/optim/ipopt_solver_test.cpp solves analytic ones)"
    "optim/solver_memory=a process-wide malloc setting made by each program's main: every optimisation of the cli tests runs under it"
    "optim/terms/objective_term=the terms' interface, exercised by every unit/optim/terms/*_term_test.cpp"
    "optim/terms/constraint_block=the blocks' interface, exercised by every unit/optim/terms/*_block_test.cpp"
    "studies/paper_report=runs every paper experiment: tests/paper/paper_report_test.cpp (label paper)")

set(problems "")
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*.h ${SOURCE_DIR}/*.cpp)
set(modules "")
foreach(source IN LISTS sources)
  string(REGEX REPLACE "(_impl)?\\.(h|cpp)$" "" module ${source})
  list(APPEND modules ${module})
endforeach()
list(REMOVE_DUPLICATES modules)

file(GLOB_RECURSE tests RELATIVE ${TEST_DIR} ${TEST_DIR}/*.cpp)
set(tested "")
foreach(test IN LISTS tests)
  if(NOT test MATCHES "_test\\.cpp$")
    string(APPEND problems "\n  tests/unit/${test}: not named <file>_test.cpp")
    continue()
  endif()
  string(REGEX REPLACE "_test\\.cpp$" "" module ${test})
  list(FIND modules ${module} index)
  if(index EQUAL -1)
    string(APPEND problems "\n  tests/unit/${test}: no src/saltus/${module}.h or .cpp")
  endif()
  list(APPEND tested ${module})
endforeach()

set(exempt "")
foreach(entry IN LISTS covered_elsewhere)
  string(REGEX REPLACE "=.*" "" module "${entry}")
  list(APPEND exempt ${module})
  list(FIND modules ${module} index)
  if(index EQUAL -1)
    string(APPEND problems "\n  mirror_sources.cmake lists ${module}, which is no library file")
  endif()
  list(FIND tested ${module} index)
  if(NOT index EQUAL -1)
    string(APPEND problems "\n  mirror_sources.cmake lists ${module}, which has its own test now")
  endif()
endforeach()

foreach(module IN LISTS modules)
  list(FIND tested ${module} has_test)
  list(FIND exempt ${module} is_exempt)
  if(has_test EQUAL -1 AND is_exempt EQUAL -1)
    string(APPEND problems "\n  src/saltus/${module}: no tests/unit/${module}_test.cpp")
  endif()
endforeach()

if(problems)
  message(FATAL_ERROR "tests/unit does not mirror src/saltus (tests/README.md):${problems}")
endif()
list(LENGTH modules module_count)
list(LENGTH tested test_count)
message(STATUS "${test_count} of ${module_count} library files have their own test; the others "
               "are listed in mirror_sources.cmake")
