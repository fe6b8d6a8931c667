// A SUNDIALS serial N_Vector seen as an Eigen vector (no copy): the one bridge between the
// integrators' vectors and the system's Eigen-valued equations.
#pragma once

#include <nvector/nvector_serial.h>

#include <Eigen/Dense>

namespace ffrf::solve::sundials {

inline Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
}

}  // namespace ffrf::solve::sundials
