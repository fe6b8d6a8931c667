// WAMIT .1, .3 and .hst readers for the planar model (see wamit_reader.hpp).
#include "hydro/wamit_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "hydro/constants.hpp"
#include "hydro/wamit_table.hpp"

namespace ffrf::hydro {

namespace {

using wamit_detail::mode_index;
using wamit_detail::PeriodBlocks;
using wamit_detail::read_rows;
using wamit_detail::Row;

constexpr std::array<int, kPlanarDofs> kWamitModes{1, 3, 5};
constexpr std::array<const char*, kPlanarDofs> kModeNames{"1 (surge)", "3 (heave)", "5 (pitch)"};

// Planar index of a WAMIT mode, or −1 when the mode is not kept.
int planar_index(int mode) {
  for (int d = 0; d < kPlanarDofs; ++d)
    if (kWamitModes[static_cast<std::size_t>(d)] == mode) return d;
  return -1;
}

int rotational_count(int i, int j) { return (i >= 4 && i <= 6 ? 1 : 0) + (j >= 4 && j <= 6 ? 1 : 0); }

void check_scaling(const WamitScaling& s) {
  auto require = [](bool ok, const char* what, double v) {
    if (!ok) throw std::invalid_argument(fmt::format("WAMIT scaling: {} = {} is invalid; valid range > 0 and finite", what, v));
  };
  require(std::isfinite(s.length) && s.length > 0.0, "ULEN [m]", s.length);
  require(std::isfinite(s.density) && s.density > 0.0, "water density [kg/m^3]", s.density);
  require(std::isfinite(s.gravity) && s.gravity > 0.0, "gravity [m/s^2]", s.gravity);
}

void require_fields(const std::string& path, const Row& row, std::size_t count, const char* form) {
  if (row.fields.size() != count)
    throw WamitFileError(path, row.line, fmt::format("{} numbers where {} are expected: {}", row.fields.size(), count, form));
}

// One period block of a pairwise (i, j) file, in planar indices.
struct PairBlock {
  PlanarMatrix first = PlanarMatrix::Zero(), second = PlanarMatrix::Zero();
  std::array<std::array<int, kPlanarDofs>, kPlanarDofs> line{};  // 0 = absent (a zero entry)
};

void store_pair(const std::string& path, const Row& row, PairBlock& block, int di, int dj, double first, double second) {
  auto& seen = block.line[static_cast<std::size_t>(di)][static_cast<std::size_t>(dj)];
  if (seen != 0)
    throw WamitFileError(path, row.line, fmt::format("entry ({}, {}) repeats the one at line {}: duplicate row",
                                                     kWamitModes[static_cast<std::size_t>(di)],
                                                     kWamitModes[static_cast<std::size_t>(dj)], seen));
  seen = row.line;
  block.first(di, dj) = first;
  block.second(di, dj) = second;
}

void require_diagonal(const std::string& path, const PairBlock& block, int first_line, const std::string& where) {
  for (int d = 0; d < kPlanarDofs; ++d)
    if (block.line[static_cast<std::size_t>(d)][static_cast<std::size_t>(d)] == 0)
      throw WamitFileError(path, first_line, fmt::format(
          "{}: no diagonal entry for mode {}; the planar model needs modes 1, 3 and 5", where, kModeNames[static_cast<std::size_t>(d)]));
}

// ρ L^(base + k) per entry, then T M T.
PlanarMatrix dimensional(const PlanarMatrix& nondimensional, double factor, double length, int base) {
  PlanarMatrix m;
  for (int i = 0; i < kPlanarDofs; ++i)
    for (int j = 0; j < kPlanarDofs; ++j) {
      const int k = rotational_count(kWamitModes[static_cast<std::size_t>(i)], kWamitModes[static_cast<std::size_t>(j)]);
      m(i, j) = kBemToPlanarSign[static_cast<std::size_t>(i)] * kBemToPlanarSign[static_cast<std::size_t>(j)] * factor *
                std::pow(length, base + k) * nondimensional(i, j);
    }
  return m;
}

std::string period_label(double period) {
  if (period < 0.0) return "zero frequency (PER < 0)";
  if (period == 0.0) return "infinite frequency (PER = 0)";
  return fmt::format("period {} s", period);
}

}  // namespace

PlanarRadiation read_wamit_radiation(const std::string& path, const WamitScaling& scaling,
                                     const WamitRadiationOptions& options) {
  check_scaling(scaling);
  const auto rows = read_rows(path, ".1 added-mass and damping");
  PeriodBlocks order(path);
  std::vector<PairBlock> blocks;
  for (const Row& row : rows) {
    if (row.fields.empty()) continue;
    const double period = row.fields[0];
    if (period <= 0.0)
      require_fields(path, row, 4, "PER I J A (PER = -1: zero frequency, PER = 0: infinite frequency)");
    else
      require_fields(path, row, 5, "PER I J A B");
    const int i = mode_index(path, row, 1, "mode I"), j = mode_index(path, row, 2, "mode J");
    const std::size_t b = order.visit(period, row.line);
    if (b == blocks.size()) blocks.emplace_back();
    const int di = planar_index(i), dj = planar_index(j);
    if (di < 0 || dj < 0) continue;
    store_pair(path, row, blocks[b], di, dj, row.fields[3], period > 0.0 ? row.fields[4] : 0.0);
  }
  PlanarRadiation result;
  result.source = path;
  struct Finite {
    double omega;
    std::size_t block;
  };
  std::vector<Finite> finite;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const double period = order.periods()[b];
    require_diagonal(path, blocks[b], order.first_lines()[b], period_label(period));
    if (period < 0.0) {
      result.has_zero_frequency = true;
      result.zero_frequency_added_mass = dimensional(blocks[b].first, scaling.density, scaling.length, 3);
    } else if (period == 0.0) {
      result.has_infinite_frequency = true;
      result.infinite_frequency_added_mass = dimensional(blocks[b].first, scaling.density, scaling.length, 3);
    } else {
      finite.push_back({kTwoPi / period, b});
    }
  }
  if (finite.empty()) throw WamitFileError(path, 0, "no finite wave period: valid files hold at least one period > 0");
  if (options.require_infinite_frequency && !result.has_infinite_frequency)
    throw WamitFileError(path, 0,
                         "no infinite-frequency limit (rows with PER = 0): the Cummins models need A(inf); rerun WAMIT "
                         "with PER = 0 among the periods");
  if (finite.size() > 1 && finite.front().omega > finite.back().omega) std::reverse(finite.begin(), finite.end());
  for (const auto& f : finite) {
    result.frequency.push_back(f.omega);
    result.added_mass.push_back(dimensional(blocks[f.block].first, scaling.density, scaling.length, 3));
    result.damping.push_back(dimensional(blocks[f.block].second, scaling.density * f.omega, scaling.length, 3));
  }
  return result;
}

PlanarExcitation read_wamit_excitation(const std::string& path, const WamitScaling& scaling) {
  check_scaling(scaling);
  const auto rows = read_rows(path, ".3 excitation");
  PeriodBlocks order(path);
  // blocks[b][heading] = (values, lines)
  struct HeadingBlock {
    double heading;
    PlanarComplexVector value = PlanarComplexVector::Zero();
    std::array<int, kPlanarDofs> line{};
  };
  std::vector<std::vector<HeadingBlock>> blocks;
  std::vector<double> headings;
  for (const Row& row : rows) {
    require_fields(path, row, 7, "PER BETA I |X| phase[deg] Re(X) Im(X)");
    const double period = row.fields[0];
    if (period <= 0.0)
      throw WamitFileError(path, row.line, fmt::format("PER = {}: excitation is defined at finite periods only; valid PER > 0", period));
    const int i = mode_index(path, row, 2, "mode I");
    const std::size_t b = order.visit(period, row.line);
    if (b == blocks.size()) blocks.emplace_back();
    const double beta = row.fields[1];
    if (b == 0 && std::find(headings.begin(), headings.end(), beta) == headings.end()) headings.push_back(beta);
    const std::complex<double> reim(row.fields[5], row.fields[6]);
    const std::complex<double> polar = std::polar(row.fields[3], row.fields[4] * std::numbers::pi / 180.0);
    if (std::abs(reim - polar) > 1e-5 * std::abs(reim) + 1e-30 + 1e-6 * row.fields[3])
      throw WamitFileError(path, row.line, fmt::format(
          "modulus/phase ({}, {} deg) and Re/Im ({}, {}) disagree: |difference| = {:.3g}; valid: the same complex "
          "number to the printed digits", row.fields[3], row.fields[4], row.fields[5], row.fields[6], std::abs(reim - polar)));
    const int d = planar_index(i);
    auto& per_heading = blocks[b];
    auto it = std::find_if(per_heading.begin(), per_heading.end(), [&](const HeadingBlock& h) { return h.heading == beta; });
    if (it == per_heading.end()) {
      per_heading.push_back({beta});
      it = per_heading.end() - 1;
    }
    if (d < 0) continue;
    auto& seen = it->line[static_cast<std::size_t>(d)];
    if (seen != 0)
      throw WamitFileError(path, row.line, fmt::format("mode {} at heading {} deg repeats line {}: duplicate row", i, beta, seen));
    seen = row.line;
    it->value(d) = reim;
  }
  PlanarExcitation result;
  result.source = path;
  result.heading_degrees = headings;
  result.force.assign(headings.size(), {});
  std::vector<std::size_t> index(blocks.size());
  for (std::size_t b = 0; b < blocks.size(); ++b) index[b] = b;
  if (blocks.size() > 1 && order.periods().front() < order.periods().back()) std::reverse(index.begin(), index.end());
  for (std::size_t b : index) {
    const double period = order.periods()[b];
    result.frequency.push_back(kTwoPi / period);
    for (std::size_t h = 0; h < headings.size(); ++h) {
      const auto it = std::find_if(blocks[b].begin(), blocks[b].end(), [&](const HeadingBlock& x) { return x.heading == headings[h]; });
      if (it == blocks[b].end())
        throw WamitFileError(path, order.first_lines()[b], fmt::format(
            "period {} s: heading {} deg (present at the first period) is missing", period, headings[h]));
      PlanarComplexVector x;
      for (int d = 0; d < kPlanarDofs; ++d) {
        if (it->line[static_cast<std::size_t>(d)] == 0)
          throw WamitFileError(path, order.first_lines()[b], fmt::format(
              "period {} s, heading {} deg: no row for mode {}; the planar model needs modes 1, 3 and 5", period,
              headings[h], kModeNames[static_cast<std::size_t>(d)]));
        const int k = rotational_count(kWamitModes[static_cast<std::size_t>(d)], 0);
        x(d) = kBemToPlanarSign[static_cast<std::size_t>(d)] * scaling.density * scaling.gravity * std::pow(scaling.length, 2 + k) * it->value(d);
      }
      result.force[h].push_back(x);
    }
  }
  return result;
}

PlanarMatrix read_wamit_hydrostatics(const std::string& path, const WamitScaling& scaling) {
  check_scaling(scaling);
  const auto rows = read_rows(path, ".hst hydrostatic stiffness");
  PairBlock block;
  for (const Row& row : rows) {
    require_fields(path, row, 3, "I J C");
    const int di = planar_index(mode_index(path, row, 0, "mode I")), dj = planar_index(mode_index(path, row, 1, "mode J"));
    if (di >= 0 && dj >= 0) store_pair(path, row, block, di, dj, row.fields[2], 0.0);
  }
  require_diagonal(path, block, 0, "hydrostatic stiffness");
  return dimensional(block.first, scaling.density * scaling.gravity, scaling.length, 2);
}

}  // namespace ffrf::hydro
