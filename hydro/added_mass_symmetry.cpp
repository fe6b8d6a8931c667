// The added mass made symmetric (see added_mass_symmetry.hpp).
#include "hydro/added_mass_symmetry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace ffrf::hydro {
namespace {

constexpr std::array<int, kPlanarDofs> kModeNumber{1, 3, 5};  // WAMIT's surge, heave, pitch

struct Entry {
  PlanarMatrix* matrix;
  TableRow where;
  double omega;
};

}  // namespace

std::string AddedMassAsymmetry::describe() const {
  if (!found()) return {};
  const auto i = static_cast<std::size_t>(row), j = static_cast<std::size_t>(column);
  const char* unit = (row == 2 || column == 2) ? "kg m" : "kg";
  std::string at;
  switch (where) {
    case TableRow::zero_frequency: at = "at zero frequency"; break;
    case TableRow::infinite_frequency: at = "at infinite frequency"; break;
    case TableRow::frequency:
      at = fmt::format("at ω = {:.6g} rad/s (period {:.6g} s)", angular_frequency, 2.0 * std::numbers::pi / angular_frequency);
      break;
  }
  return fmt::format("A{}{} = {:.6g} {} against A{}{} = {:.6g} {} ({:.3g} %) {}", kModeNumber[i], kModeNumber[j], upper, unit,
                     kModeNumber[j], kModeNumber[i], lower, unit, 100.0 * relative, at);
}

AddedMassAsymmetry symmetrise_added_mass(PlanarRadiation& radiation) {
  std::vector<Entry> entries;
  if (radiation.has_zero_frequency) entries.push_back({&radiation.zero_frequency_added_mass, TableRow::zero_frequency, 0.0});
  if (radiation.has_infinite_frequency) {
    entries.push_back({&radiation.infinite_frequency_added_mass, TableRow::infinite_frequency, 0.0});
  }
  for (std::size_t k = 0; k < radiation.added_mass.size(); ++k) {
    entries.push_back({&radiation.added_mass[k], TableRow::frequency, k < radiation.frequency.size() ? radiation.frequency[k] : 0.0});
  }
  AddedMassAsymmetry worst;
  for (int i = 0; i < kPlanarDofs; ++i) {
    for (int j = i + 1; j < kPlanarDofs; ++j) {
      double largest = 0.0;  // the pair's largest magnitude in the table
      for (const Entry& e : entries) largest = std::max({largest, std::abs((*e.matrix)(i, j)), std::abs((*e.matrix)(j, i))});
      if (!(largest > 0.0)) continue;
      for (const Entry& e : entries) {
        const double upper = (*e.matrix)(i, j), lower = (*e.matrix)(j, i);
        const double size = std::max(std::abs(upper), std::abs(lower));
        if (size < significant_share * largest) continue;
        const double relative = std::abs(upper - lower) / size;
        if (relative > worst.relative) worst = {relative, i, j, e.where, e.omega, upper, lower};
      }
    }
  }
  for (const Entry& e : entries) *e.matrix = 0.5 * (*e.matrix + e.matrix->transpose()).eval();
  return worst;
}

}  // namespace ffrf::hydro
