// A study file that binds itself to Python on purpose (tests/architecture/CMakeLists.txt): pybind11
// belongs to python/ alone. Not compiled.
#include <pybind11/pybind11.h>
