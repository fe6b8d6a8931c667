# Precompiled headers (docs/building.md): nearly every file parses Eigen's dense module and the same
# standard headers, and every test file also GoogleTest — 1–3 s of GCC's time per file at -O3 before
# any of the file's own code. Two headers compiled once per build carry them: one for the libraries
# listed in the top-level CMakeLists.txt, one for the test programs (the same plus GoogleTest;
# ffrf_add_gtest in tests/CMakeLists.txt). Every such target reuses one of them (REUSE_FROM), so
# they must all be compiled with the same flags (ffrf_warnings). Only headers whose meaning no
# target's definitions change are listed (not fmt: fmt::fmt defines FMT_SHARED).
# `-DFFRF_PRECOMPILED_HEADERS=OFF` builds without them (each file includes what it names, as it must
# anyway: the precompiled header is an optimisation, not an include).
# Through a precompiled header GCC 12 at -O3 reports false -Wstringop-overflow / -Warray-bounds on
# some std::string concatenations that it does not report without one; the files concerned append
# piece by piece instead. study/, report/ and app/ have not been checked for them and compile
# without a precompiled header.
option(FFRF_PRECOMPILED_HEADERS "Precompile Eigen, GoogleTest and standard headers once per build" ON)

set(ffrf_precompiled_headers
  <Eigen/Dense> <algorithm> <array> <chrono> <cmath> <complex> <cstdio> <cstdlib> <filesystem> <fstream>
  <functional> <limits> <map> <memory> <numbers> <optional> <set> <sstream> <stdexcept> <string>
  <string_view> <utility> <vector>)

if(FFRF_PRECOMPILED_HEADERS)
  file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/ffrf_precompiled_headers.cpp
       CONTENT "// Compiles ffrf's precompiled headers (cmake/FfrfPrecompiledHeaders.cmake).\n")
  add_library(ffrf_pch_library OBJECT ${PROJECT_BINARY_DIR}/ffrf_precompiled_headers.cpp)
  target_link_libraries(ffrf_pch_library PRIVATE Eigen3::Eigen ffrf_warnings)
  target_precompile_headers(ffrf_pch_library PRIVATE ${ffrf_precompiled_headers})
endif()

# The libraries' precompiled header for `target`.
function(ffrf_use_library_pch target)
  if(FFRF_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} REUSE_FROM ffrf_pch_library)
  endif()
endfunction()

# The test programs' precompiled header for `target`; made on first use, with the test programs'
# compile definitions.
function(ffrf_use_test_pch target)
  if(NOT FFRF_PRECOMPILED_HEADERS)
    return()
  endif()
  if(NOT TARGET ffrf_pch_tests)
    add_library(ffrf_pch_tests OBJECT ${PROJECT_BINARY_DIR}/ffrf_precompiled_headers.cpp)
    target_link_libraries(ffrf_pch_tests PRIVATE Eigen3::Eigen GTest::gtest ffrf_warnings)
    target_compile_definitions(ffrf_pch_tests PRIVATE FFRF_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                      FFRF_BINARY_DIR="${PROJECT_BINARY_DIR}")
    target_precompile_headers(ffrf_pch_tests PRIVATE <gtest/gtest.h> ${ffrf_precompiled_headers})
    ffrf_light_optimisation(ffrf_pch_tests)  # the test programs' level, which the header must match
  endif()
  target_precompile_headers(${target} REUSE_FROM ffrf_pch_tests)
endfunction()

# ccache serves files compiled with a precompiled header from its cache only with the sloppiness
# `pch_defines,time_macros` (ccache manual, "Precompiled headers"; no file of ffrf uses __DATE__ or
# __TIME__): when the launcher is ccache, it runs with those added to the configured sloppiness.
if(FFRF_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_LAUNCHER)
  set(launcher)
  foreach(part IN LISTS CMAKE_CXX_COMPILER_LAUNCHER)
    get_filename_component(program "${part}" NAME)
    if(program STREQUAL "ccache")
      execute_process(COMMAND ${part} --get-config sloppiness OUTPUT_VARIABLE sloppiness
                      OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      string(REPLACE " " "" sloppiness "${sloppiness}")
      list(APPEND sloppiness pch_defines time_macros)
      list(REMOVE_ITEM sloppiness "")
      list(REMOVE_DUPLICATES sloppiness)
      list(JOIN sloppiness "," sloppiness)
      list(APPEND launcher ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=${sloppiness})
    endif()
    list(APPEND launcher "${part}")
  endforeach()
  set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
endif()
