// Validation of a beam mesh and its section: every constant must be finite and positive.
#include "fem/mesh.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ffrf::fem {
namespace {

void require_positive(double value, const char* what, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(std::string(what) + " = " + std::to_string(value) + " " + unit +
                                ": must be finite and > 0");
  }
}

}  // namespace

void validate(const BeamMesh& mesh) {
  require_positive(mesh.length, "beam length", "m");
  if (mesh.element_count < 1) {
    throw std::invalid_argument("element count = " + std::to_string(mesh.element_count) + ": must be >= 1");
  }
  require_positive(mesh.section.youngs_modulus, "Young's modulus E", "Pa");
  require_positive(mesh.section.area, "section area A", "m^2");
  require_positive(mesh.section.second_moment, "second moment of area I", "m^4");
  require_positive(mesh.section.mass_per_length, "mass per length", "kg/m");
}

}  // namespace ffrf::fem
