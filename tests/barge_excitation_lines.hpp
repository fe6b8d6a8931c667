// The WAMIT barge fixture's excitation (tests/hydro/data/barge.3) read from the file's lines by the
// tests themselves, independently of hydro/wamit_reader: at one tabulated period and heading 0,
// X_i = ρ g (Re + i Im) per metre of amplitude (ULEN = 1: L^(2+k) = 1), pitch sign flipped (WAMIT's
// mode 5 is bow-down), surge, heave, pitch at the BEM body origin.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <fstream>
#include <sstream>
#include <string>

namespace ffrf::test_text {

inline Eigen::Vector3cd barge_file_excitation(double period, double rho, double g) {
  std::string path = FFRF_SOURCE_DIR;  // appended: a false -Warray-bounds of GCC 12 through the PCH on `+`
  path += "/tests/hydro/data/barge.3";
  std::ifstream in(path);
  std::string line;
  Eigen::Vector3cd x = Eigen::Vector3cd::Zero();
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double tabulated = 0, heading = 0, modulus = 0, phase = 0, re = 0, im = 0;
    int mode = 0;
    if (!(fields >> tabulated >> heading >> mode >> modulus >> phase >> re >> im)) continue;
    if (std::abs(tabulated - period) > 1e-9 || heading != 0.0) continue;
    const int index = mode == 1 ? 0 : mode == 3 ? 1 : 2;
    x(index) = rho * g * std::complex<double>(re, im) * (mode == 5 ? -1.0 : 1.0);
  }
  return x;
}

}  // namespace ffrf::test_text
