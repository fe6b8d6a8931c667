// The stability region of the explicit table (see erk_stability_region.hpp).
#include "solve/erk_stability_region.hpp"

#include <arkode/arkode_erkstep.h>

#include <cmath>
#include <vector>

namespace ffrf::solve {
namespace {

struct ButcherTable {
  ARKodeButcherTable table = ARKodeButcherTable_LoadERK(explicit_table_id);
  ButcherTable() = default;
  ~ButcherTable() { ARKodeButcherTable_Free(table); }
  ButcherTable(const ButcherTable&) = delete;
  ButcherTable& operator=(const ButcherTable&) = delete;
};

const ARKodeButcherTableMem& erk_table() {
  static const ButcherTable table;
  return *table.table;
}

}  // namespace

std::complex<double> explicit_stability_function(std::complex<double> w) {
  const ARKodeButcherTableMem& table = erk_table();
  std::vector<std::complex<double>> stages(static_cast<std::size_t>(table.stages));
  std::complex<double> sum = 0.0;
  for (int i = 0; i < table.stages; ++i) {
    std::complex<double> stage = 1.0;
    for (int j = 0; j < i; ++j) stage += w * table.A[i][j] * stages[static_cast<std::size_t>(j)];
    stages[static_cast<std::size_t>(i)] = stage;
    sum += table.b[i] * stage;
  }
  return 1.0 + w * sum;
}

double explicit_ray_boundary(std::complex<double> direction) {
  constexpr double ds = 0.005, s_max = 20.0, slack = 1e-9;
  const std::complex<double> d = direction / std::abs(direction);
  double good = 0.0;
  for (double s = ds; s <= s_max; s += ds) {
    if (std::abs(explicit_stability_function(s * d)) > 1.0 + slack) {
      double bad = s;
      for (int i = 0; i < 50; ++i) {
        const double mid = 0.5 * (good + bad);
        (std::abs(explicit_stability_function(mid * d)) > 1.0 + slack ? bad : good) = mid;
      }
      return good;
    }
    good = s;
  }
  return s_max;
}

}  // namespace ffrf::solve
