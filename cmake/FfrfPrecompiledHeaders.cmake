# Precompiled header of the test programs (docs/building.md): every test file parses GoogleTest,
# Eigen's dense module and the same standard headers — 1.5–3 s of GCC's time per file at -O3
# before any of the file's own code. One header compiled once per build carries them, and every
# test program reuses it (REUSE_FROM; ffrf_add_gtest in tests/CMakeLists.txt), so all test programs
# must be compiled with the same flags (ffrf_warnings) and definitions (FFRF_SOURCE_DIR,
# FFRF_BINARY_DIR). Only headers whose meaning no test's definitions change are listed (not fmt:
# fmt::fmt defines FMT_SHARED). `-DFFRF_PRECOMPILED_HEADERS=OFF` builds without it (each file
# includes what it names, as it must anyway: the precompiled header is an optimisation, not an
# include). The libraries do not use one: through a precompiled header GCC 12 at -O3 reports false
# -Wstringop-overflow warnings on std::string concatenations in several library files
# (docs/building.md).
option(FFRF_PRECOMPILED_HEADERS "Precompile GoogleTest, Eigen and standard headers once for all tests" ON)

set(ffrf_test_precompiled_headers
  <gtest/gtest.h> <Eigen/Dense> <algorithm> <array> <chrono> <cmath> <complex> <cstdio> <cstdlib>
  <filesystem> <fstream> <functional> <limits> <map> <memory> <numbers> <optional> <set> <sstream>
  <stdexcept> <string> <string_view> <utility> <vector>)

# The test programs' precompiled header for `target`; made on first use.
function(ffrf_use_test_pch target)
  if(NOT FFRF_PRECOMPILED_HEADERS)
    return()
  endif()
  if(NOT TARGET ffrf_pch_tests)
    file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/ffrf_precompiled_headers.cpp
         CONTENT "// Compiles the tests' precompiled header (cmake/FfrfPrecompiledHeaders.cmake).\n")
    add_library(ffrf_pch_tests OBJECT ${PROJECT_BINARY_DIR}/ffrf_precompiled_headers.cpp)
    target_link_libraries(ffrf_pch_tests PRIVATE Eigen3::Eigen GTest::gtest ffrf_warnings)
    target_compile_definitions(ffrf_pch_tests PRIVATE FFRF_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                                                      FFRF_BINARY_DIR="${PROJECT_BINARY_DIR}")
    target_precompile_headers(ffrf_pch_tests PRIVATE ${ffrf_test_precompiled_headers})
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
