# The layering of docs/architecture.md, checked on the sources (ctest `architecture_layers`):
#   linalg (dense Eigen solvers compiled once) <- fem <- modal, nodal <- multibody <- scene <- study <-
#   report <- app, with hydro on linalg and sea (the sea's loads on a hull) on hydro beside them
#   (multibody may use sea and hydro; neither knows anything of the crane), and solve (the solvers of
#   a generic second-order system) on linalg alone: multibody implements its system interface, and
#   solve knows nothing of fem, modal, nodal, hydro, sea or the crane; distributed/ (the task-farm engine)
#   knows nothing of ffrf and serves study/ and app/;
#   python/ (the Python module) on scene, study and report (and solve's stop requests and failures,
#   distributed's session) beside app, which it never includes;
#   CLI11 only in app/, nlohmann-json only in report/, toml++ only in scene/, netCDF only in hydro/,
#   pybind11 only in python/;
#   no printing (fmt::print, printf, std::cout/cerr, puts) in scene/, study/, report/, python/;
#   the test programs of tests/<layer> link no library of a layer above it.
# Run as: cmake -DSOURCE_DIR=<repository> -P check_layers.cmake. Every violation is listed with its
# file and line; the script fails when there is one.
cmake_minimum_required(VERSION 3.25)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "give -DSOURCE_DIR=<repository root>")
endif()

# Which library folders a folder may include from (itself always).
set(allowed_linalg "")
set(allowed_fem linalg)
set(allowed_modal linalg fem)
set(allowed_nodal linalg fem)
set(allowed_hydro linalg)
set(allowed_distributed "")
set(allowed_sea linalg hydro)
set(allowed_solve linalg)
set(allowed_multibody linalg fem modal nodal hydro sea solve)
set(allowed_scene linalg fem modal nodal hydro sea solve multibody)
set(allowed_study linalg fem modal nodal hydro sea solve multibody scene distributed)
set(allowed_report linalg fem modal nodal hydro sea solve multibody scene study distributed)
set(allowed_app linalg fem modal nodal hydro sea solve multibody scene study report distributed)
set(allowed_python solve scene study report distributed)
set(layers linalg fem modal nodal hydro sea distributed solve multibody scene study report app python)

set(violations "")
set(checked 0)
foreach(layer IN LISTS layers)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/${layer}")
    continue()
  endif()
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${layer}/*.hpp" "${SOURCE_DIR}/${layer}/*.cpp" "${SOURCE_DIR}/${layer}/*.ipp")
  foreach(source IN LISTS sources)
    math(EXPR checked "${checked} + 1")
    file(RELATIVE_PATH shown "${SOURCE_DIR}" "${source}")
    file(STRINGS "${source}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([a-z_]+)/")
        set(target "${CMAKE_MATCH_1}")
        if(NOT target STREQUAL layer AND target IN_LIST layers AND NOT target IN_LIST allowed_${layer})
          list(APPEND violations "${shown}:${number}: ${layer}/ must not include ${target}/ (${line})")
        endif()
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<CLI/" AND NOT layer STREQUAL "app")
        list(APPEND violations "${shown}:${number}: CLI11 outside app/ (${line})")
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<nlohmann/" AND NOT layer STREQUAL "report")
        list(APPEND violations "${shown}:${number}: nlohmann-json outside report/ (${line})")
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<toml" AND NOT layer STREQUAL "scene")
        list(APPEND violations "${shown}:${number}: toml++ outside scene/ (${line})")
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<netcdf" AND NOT layer STREQUAL "hydro")
        list(APPEND violations "${shown}:${number}: netCDF outside hydro/ (${line})")
      endif()
      if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<pybind11/" AND NOT layer STREQUAL "python")
        list(APPEND violations "${shown}:${number}: pybind11 outside python/ (${line})")
      endif()
      if(layer MATCHES "^(scene|study|report|python)$" AND
         line MATCHES "(fmt::print|std::cout|std::cerr|std::clog|[^a-z_]printf[ \t]*\\(|[^a-z_]puts[ \t]*\\()")
        list(APPEND violations "${shown}:${number}: ${layer}/ prints (it returns results; app/ prints) (${line})")
      endif()
    endforeach()
  endforeach()
endforeach()

# The test programs of a layer (tests/<layer>/CMakeLists.txt) link only that layer's library and
# the libraries below it: a library named ffrf_<layer> of another layer must be an allowed one.
foreach(layer IN LISTS layers)
  set(tests_file "${SOURCE_DIR}/tests/${layer}/CMakeLists.txt")
  if(NOT EXISTS "${tests_file}")
    continue()
  endif()
  math(EXPR checked "${checked} + 1")
  file(STRINGS "${tests_file}" lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "^[ \t]*#")
      continue()
    endif()
    string(REGEX MATCHALL "ffrf_[a-z]+" libraries "${line}")
    foreach(library IN LISTS libraries)
      string(REGEX REPLACE "^ffrf_" "" target "${library}")
      if(NOT target STREQUAL layer AND target IN_LIST layers AND NOT target IN_LIST allowed_${layer})
        list(APPEND violations "tests/${layer}/CMakeLists.txt:${number}: a test of ${layer}/ must not link ${library} (${line})")
      endif()
    endforeach()
  endforeach()
endforeach()

if(checked EQUAL 0)
  message(FATAL_ERROR "no sources found below ${SOURCE_DIR}")
endif()
list(LENGTH violations count)
if(count GREATER 0)
  list(JOIN violations "\n" text)
  message(FATAL_ERROR "${count} layering violation(s) (docs/architecture.md):\n${text}")
endif()
message(STATUS "layering: ${checked} files follow docs/architecture.md")
