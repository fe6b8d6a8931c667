// The 10-m steel cantilever of the modal tests (E 210 GPa, A 0.01 m², I 8.333e-6 m⁴, 78.5 kg/m),
// clamped at its root, on `elements` beam elements.
#pragma once

#include <memory>

#include "fem/beam_model.hpp"

namespace ffrf::test {

inline std::shared_ptr<const fem::BeamModel> cantilever(int elements) {
  return std::make_shared<const fem::BeamModel>(
      fem::make_beam_model({10.0, elements, {2.1e11, 0.01, 8.333e-6, 78.5}}, fem::Boundary::clamped_free));
}

}  // namespace ffrf::test
