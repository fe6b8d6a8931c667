// The RAO charts' scripts (report/rao_charts.hpp): every resonant natural period inside the band is
// a vertical line at 2π/ω_n (read back from the script), labelled once per distinct period; modes
// outside the band or without a resonance are not drawn; a sea spectrum is drawn on the amplitude
// panels' second axis from sea_spectrum.csv, whose densities are the spectrum's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "report/rao_charts.hpp"
#include "study/rao_spectrum.hpp"

namespace ffrf {
namespace {

study::ModelRao model(scene::BoomKind kind, std::vector<study::NaturalMode> modes, const std::vector<double>& omegas) {
  study::ModelRao m;
  m.choice = {kind, kind == scene::BoomKind::rigid ? 1 : 12};
  m.modes = std::move(modes);
  m.angular_frequencies = omegas;
  for (auto& values : m.response) values.assign(omegas.size(), {1.0, 0.0});
  return m;
}

// The x coordinates of the script's `set arrow N from X, graph 0 ...` lines.
std::vector<double> arrow_positions(const std::string& script) {
  std::vector<double> out;
  std::istringstream lines(script);
  for (std::string line; std::getline(lines, line);) {
    const auto from = line.find(" from ");
    if (line.rfind("set arrow ", 0) == 0 && from != std::string::npos) out.push_back(std::stod(line.substr(from + 6)));
  }
  return out;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RaoCharts, NaturalPeriodsAreMarkedAndTheSeaIsOnTheSecondAxis) {
  study::RaoResult result;
  result.angular_frequencies = {2.0 * std::numbers::pi / 30.0, 0.5, 1.0, 2.0 * std::numbers::pi / 3.0};
  const double cargo = 0.5264, heave = 0.8417;
  result.models.push_back(model(scene::BoomKind::rigid,
                                {{0.1765, 0.02, "hull surge", ""},   // 35.6 s: outside the band
                                 {cargo, 0.015, "cargo surge", ""},
                                 {heave, 0.04, "hull heave", ""},
                                 {1.2, 0.9, "boom", ""},             // no resonance
                                 {15.3, 0.025, "cargo heave", ""}},  // 0.41 s: outside
                                result.angular_frequencies));
  result.models.push_back(model(scene::BoomKind::nodal, {{cargo * 1.002, 0.015, "cargo surge", ""}}, result.angular_frequencies));
  const std::string script = report::rao_chart_script("rao_cargo", result, "pngcairo");
  const std::vector<double> arrows = arrow_positions(script);
  const std::vector<double> expected{2.0 * std::numbers::pi / cargo, 2.0 * std::numbers::pi / heave,
                                     2.0 * std::numbers::pi / (cargo * 1.002)};
  ASSERT_EQ(arrows.size(), expected.size()) << script;
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(arrows[i] / expected[i], 1.0, 1e-5) << i;
  EXPECT_EQ(count(script, "cargo surge 11.94 s"), 1u) << script;  // the nodal model's 0.2 % off: drawn, not labelled again
  EXPECT_EQ(count(script, "hull heave 7.465 s"), 1u) << script;
  EXPECT_EQ(count(script, "axes x1y2"), 0u);

  result.sea = study::sea_weighting(hydro::jonswap(1.5, 9.0, 3.3), result.angular_frequencies.front(), result.angular_frequencies.back());
  const std::string with_sea = report::rao_chart_script("rao_cargo", result, "pngcairo");
  EXPECT_EQ(count(with_sea, "'sea_spectrum.csv' skip 1 using 1:3 axes x1y2"), 3u);  // the three amplitude panels
  EXPECT_EQ(count(with_sea, "JONSWAP Hs 1.5 m, Tp 9 s"), 3u);
  const std::string csv = report::sea_spectrum_csv(result);
  std::istringstream rows(csv);
  std::string header;
  std::getline(rows, header);
  EXPECT_EQ(header, "period_s,angular_frequency_rad_per_s,density_m2_s_per_rad");
  int n = 0;
  for (std::string row; std::getline(rows, row); ++n) {
    double period = 0.0, omega = 0.0, density = 0.0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf", &period, &omega, &density), 3) << row;
    EXPECT_NEAR(omega * period, 2.0 * std::numbers::pi, 1e-8);
    EXPECT_NEAR(density, hydro::spectral_density(result.sea->spectrum, omega), 1e-9 * (1.0 + density)) << row;
  }
  EXPECT_EQ(n, 400);
}

}  // namespace
}  // namespace ffrf
