// numpy arrays of the studies' results (see bindings.hpp): copies, so that a result outlives the
// study's structures. The one file that includes pybind11's numpy support.
#include <pybind11/numpy.h>

#include <algorithm>

#include "python/bindings.hpp"

namespace ffrf::python {

py::object array_of(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::object complex_array_of(const std::vector<std::complex<double>>& values) {
  py::array_t<std::complex<double>> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::object matrix_of(const Eigen::MatrixXd& values) {
  py::array_t<double> array({static_cast<py::ssize_t>(values.rows()), static_cast<py::ssize_t>(values.cols())});
  auto view = array.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    for (Eigen::Index j = 0; j < values.cols(); ++j) view(i, j) = values(i, j);
  }
  return array;
}

}  // namespace ffrf::python
