// A solver file that reaches into the crane on purpose (tests/architecture/CMakeLists.txt): the
// solvers see only solve/second_order_system.hpp, never the multibody model or the elements.
// Not compiled.
#include "fem/beam_element.hpp"
#include "multibody/crane_equations.hpp"
