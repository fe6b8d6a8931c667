# FfrfBaseline.cmake: regression baselines of ffrf as ctest tests of your own project
# (docs/baselines.md).
#
#   include(<ffrf checkout>/cmake/FfrfBaseline.cmake)         # from a source checkout, or
#   include(<prefix>/share/ffrf/cmake/FfrfBaseline.cmake)      # after `cmake --install <ffrf build>`
#
#   ffrf_add_baseline_test(<name> <scene.toml> <baseline.json>
#                          [FFRF <program>] [ARGS <option>...] [LABELS <label>...]
#                          [WORKING_DIRECTORY <dir>] [TIMEOUT <seconds>])
#
# adds the ctest <name>, which runs `ffrf baseline check <scene> <baseline> <ARGS>`: it passes when
# every recorded quantity is within its tolerance, and fails on a regression (ffrf exits 4), on bad
# input (2: missing or malformed scene or baseline) and when a solver fails (3). Relative paths are
# taken from the current source directory. ARGS are passed to the check as they are (tolerances
# such as `--rtol 1e-3` or `--tolerance wire_tension_N=1e-3`, or model options).
#
# The ffrf program, first found of:
#   1. FFRF <program> given to the call;
#   2. the CMake target `ffrf`, when the project builds ffrf itself (add_subdirectory, ffrf's own suite);
#   3. the cache variable FFRF_EXECUTABLE: `-DFFRF_EXECUTABLE=<ffrf build>/app/ffrf` uses a build tree;
#   4. `ffrf` in the bin/ directory of the prefix this file was installed to, then on PATH.
cmake_minimum_required(VERSION 3.20)
include_guard(GLOBAL)

set(_ffrf_baseline_module_dir "${CMAKE_CURRENT_LIST_DIR}")

function(ffrf_add_baseline_test name scene baseline)
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "FFRF;WORKING_DIRECTORY;TIMEOUT" "ARGS;LABELS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "ffrf_add_baseline_test(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS} "
                        "(valid: FFRF, ARGS, LABELS, WORKING_DIRECTORY, TIMEOUT)")
  endif()
  if(arg_FFRF)
    set(program "${arg_FFRF}")
  elseif(TARGET ffrf)
    set(program "$<TARGET_FILE:ffrf>")
  else()
    if(NOT FFRF_EXECUTABLE)
      # <prefix>/share/ffrf/cmake/ -> <prefix>/bin
      find_program(FFRF_EXECUTABLE ffrf HINTS "${_ffrf_baseline_module_dir}/../../../bin"
                   DOC "The ffrf program that runs the baseline checks")
    endif()
    if(NOT FFRF_EXECUTABLE)
      message(FATAL_ERROR "ffrf_add_baseline_test(${name}): no ffrf program found: give FFRF <program>, or configure "
                          "with -DFFRF_EXECUTABLE=<ffrf build>/app/ffrf, or install ffrf (cmake --install) into a "
                          "prefix on PATH")
    endif()
    set(program "${FFRF_EXECUTABLE}")
  endif()
  get_filename_component(scene_path "${scene}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(baseline_path "${baseline}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  set(directory "${CMAKE_CURRENT_BINARY_DIR}")
  if(arg_WORKING_DIRECTORY)
    set(directory "${arg_WORKING_DIRECTORY}")
  endif()
  add_test(NAME ${name} COMMAND "${program}" baseline check "${scene_path}" "${baseline_path}" ${arg_ARGS}
           WORKING_DIRECTORY "${directory}")
  # (No REQUIRED_FILES: a missing scene or baseline is named by ffrf itself, exit 2.)
  set_property(TEST ${name} APPEND PROPERTY LABELS ffrf_baseline ${arg_LABELS})
  if(arg_TIMEOUT)
    set_property(TEST ${name} PROPERTY TIMEOUT ${arg_TIMEOUT})
  endif()
endfunction()
