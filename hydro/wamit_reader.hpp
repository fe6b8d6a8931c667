// WAMIT numeric output files (WAMIT User Manual v7, ch. 4 "Output"), read for the planar model:
//   .1   PER I J Ā_ij B̄_ij   (PER = −1: zero frequency, PER = 0: infinite frequency, 4 columns)
//   .3   PER β I |X̄_i| arg X̄_i [deg] Re X̄_i Im X̄_i
//   .hst I J C̄_ij
// PER is the wave period [s] (WAMIT's default output, IPERO = 1). Dimensional values (manual §4.1),
// with L = ULEN, ρ, g the run's values and k = the number of rotational modes (4–6) among the indices:
//   A_ij = ρ L^(3+k) Ā_ij,  B_ij = ρ ω L^(3+k) B̄_ij,  C_ij = ρ g L^(2+k) C̄_ij,  X_i = ρ g L^(2+k) X̄_i
// (X per unit wave amplitude). Modes 1, 3, 5 (surge, heave, pitch) are kept. WAMIT has z up and
// mode 5 a rotation about +y, which lowers the bow (x > 0 goes down); ffrf's pitch is
// counter-clockwise in the x–y plane, bow up. So q_ffrf = T q_wamit with T = diag(1, 1, −1), and
// A, B, C become T M T (the surge–pitch and heave–pitch couplings change sign), X becomes T X. WAMIT's
// +x is taken as ffrf's +x (forward); heading β = 0 is a wave travelling +x (ffrf's following sea),
// β = 180° travelling −x (head sea). Coefficients refer to the BEM body origin (XBODY).
// Errors: WamitFileError naming the file, the line, what is wrong and the valid form or range.
#pragma once

#include <stdexcept>
#include <string>

#include "hydro/planar_coefficients.hpp"

namespace ffrf::hydro {

class WamitFileError : public std::runtime_error {
 public:
  WamitFileError(std::string file, int line, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 0 when the problem is the file as a whole

 private:
  std::string file_;
  int line_;
};

struct WamitScaling {
  double length = 1.0;      // ULEN [m]
  double density = 1025.0;  // ρ [kg/m³]
  double gravity = 9.81;    // g [m/s²]
};

struct WamitRadiationOptions {
  bool require_infinite_frequency = true;  // PER = 0 block must be present (Cummins needs A∞)
};

PlanarRadiation read_wamit_radiation(const std::string& path, const WamitScaling& scaling,
                                     const WamitRadiationOptions& options = {});
PlanarExcitation read_wamit_excitation(const std::string& path, const WamitScaling& scaling);
PlanarMatrix read_wamit_hydrostatics(const std::string& path, const WamitScaling& scaling);

}  // namespace ffrf::hydro
