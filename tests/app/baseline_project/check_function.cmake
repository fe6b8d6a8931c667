# ctest `baseline_cmake_function`: the CMake function users call (cmake/FfrfBaseline.cmake) works
# from ffrf's build tree and from an installed prefix. Records a baseline of a short run of the
# reference crane and a deliberately wrong one (the same crane with E x 1.01), configures the user
# project of this folder against each way of finding ffrf, and asserts that the generated test
# passes on the right baseline, fails on the wrong one, and that the wrong one's command, run
# directly, exits with 4 (a regression), not 2 or 3.
# Run as: cmake -DFFRF=<ffrf> -DSOURCE_DIR=<repository> -DBINARY_DIR=<ffrf build> -DSCRATCH=<dir> -P check_function.cmake
cmake_minimum_required(VERSION 3.25)
foreach(variable FFRF SOURCE_DIR BINARY_DIR SCRATCH)
  if(NOT ${variable})
    message(FATAL_ERROR "give -D${variable}=...")
  endif()
endforeach()
set(project_dir "${CMAKE_CURRENT_LIST_DIR}")
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")

function(run expected)  # run(<expected exit code> COMMAND...)
  execute_process(COMMAND ${ARGN} INPUT_FILE /dev/null RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code STREQUAL expected)
    list(JOIN ARGN " " command)
    message(FATAL_ERROR "`${command}` exited with ${code}, expected ${expected}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
endfunction()

# The baselines: one of the scene, one of a stiffer boom.
set(scene "${SOURCE_DIR}/cases/paper_floating_crane.toml")
file(READ "${scene}" text)
string(REPLACE "youngs_modulus = 2.1e11" "youngs_modulus = 2.121e11" stiffer "${text}")
if(stiffer STREQUAL text)
  message(FATAL_ERROR "the scene has no `youngs_modulus = 2.1e11` to change")
endif()
file(WRITE "${SCRATCH}/stiffer.toml" "${stiffer}")
run(0 "${FFRF}" baseline record "${scene}" -N 4 --duration 22 --out "${SCRATCH}/right.json")
run(0 "${FFRF}" baseline record "${SCRATCH}/stiffer.toml" -N 4 --duration 22 --out "${SCRATCH}/wrong.json")

# Configures the user project in `build` with `options`, then checks its two tests.
function(check_user_project build)
  run(0 ${CMAKE_COMMAND} -S "${project_dir}" -B "${SCRATCH}/${build}" -DSCENE=${scene} -DRIGHT=${SCRATCH}/right.json
      -DWRONG=${SCRATCH}/wrong.json ${ARGN})
  run(0 ${CMAKE_CTEST_COMMAND} --test-dir "${SCRATCH}/${build}" -R "^crane_right$" --output-on-failure)
  # ctest fails when a test fails (exit 8); the test's own command says why: exit 4, a regression.
  execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${SCRATCH}/${build}" -R "^crane_wrong$" INPUT_FILE /dev/null
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
  if(code EQUAL 0)
    message(FATAL_ERROR "${build}: the check against the wrong baseline passed")
  endif()
  execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${SCRATCH}/${build}" --show-only=json-v1
                  INPUT_FILE /dev/null OUTPUT_VARIABLE listing RESULT_VARIABLE code)
  string(JSON count LENGTH "${listing}" tests)
  if(NOT count EQUAL 2)
    message(FATAL_ERROR "${build}: expected the 2 tests of the user project, ctest lists ${count}")
  endif()
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${listing}" tests ${i} name)
    string(JSON words LENGTH "${listing}" tests ${i} command)
    set(command "")
    math(EXPR last_word "${words} - 1")
    foreach(j RANGE ${last_word})
      string(JSON word GET "${listing}" tests ${i} command ${j})
      list(APPEND command "${word}")
    endforeach()
    list(GET command 0 program)
    set(${build}_program "${program}" PARENT_SCOPE)
    if(name STREQUAL "crane_wrong")
      run(4 ${command})
    else()
      run(0 ${command})
    endif()
  endforeach()
endfunction()

# 1. From ffrf's build tree: the module by path in the source checkout, FFRF_EXECUTABLE set.
check_user_project(build-tree -DFFRF_MODULE=${SOURCE_DIR}/cmake/FfrfBaseline.cmake -DFFRF_EXECUTABLE=${FFRF})

# 2. Installed: `cmake --install` into a prefix; the module finds <prefix>/bin/ffrf by itself.
run(0 ${CMAKE_COMMAND} --install "${BINARY_DIR}" --prefix "${SCRATCH}/prefix")
check_user_project(installed -DFFRF_MODULE=${SCRATCH}/prefix/share/ffrf/cmake/FfrfBaseline.cmake)
if(NOT installed_program STREQUAL "${SCRATCH}/prefix/bin/ffrf")
  message(FATAL_ERROR "the installed module ran ${installed_program}, not ${SCRATCH}/prefix/bin/ffrf")
endif()

file(REMOVE_RECURSE "${SCRATCH}")
message(STATUS "ffrf_add_baseline_test: passes on the right baseline and exits 4 on the wrong one, from the build tree and installed")
