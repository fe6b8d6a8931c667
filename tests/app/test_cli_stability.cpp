// `ffrf stability --quick` end to end on the spin-up beam and the dropped load, asserting the physics
// in summary.json against hand results: the unstiffened linear floating frame fails during the
// spin-up as Ω(t) approaches the first bending frequency ω1 = 1.8751²√(EI/(ρA L⁴)) (its bending
// stiffness K(1 − Ω²/ω1²) goes to zero), the centrifugally stiffened runs stay bounded, BDF 3–5 need
// many more steps than BDF 2 on the undamped boom, the index-1 drift exceeds the stabilized one, the
// dropped load's snap peak is k(s + A) and its free fall lasts √(2(d − s)/g) (the scene file's hand
// derivation), and the root compression is (ρA L + m) g sin φ; bad input exits 2.
#include <cmath>
#include <map>
#include <numbers>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace {

Json stability_summary(const TempDir& dir, const std::string& scene) {
  const RunResult r = run_ffrf("stability '" + source_file(scene) + "' --quick --out '" + (dir / "out").string() + "'",
                               dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out/report.md"));
  return JsonParser(read_text(dir / "out/summary.json")).parse();
}

double extra(const Json& cell, const std::string& name) { return cell[name].number; }

TEST(CliStability, SpinUpUnstiffenedDivergesOnceTheSpinPassesTheFirstBendingFrequencyStiffenedStaysBounded) {
  TempDir dir;
  const Json summary = stability_summary(dir, "cases/spin_up_beam.toml");
  // Scene: EI = 7e10 · 2e-7 N m², ρA = 1.2 kg/m, L = 10 m, spin-up over Ts = 15 s, divergence at 0.5 L.
  const double omega1 = 1.875104068711961 * 1.875104068711961 * std::sqrt(7e10 * 2e-7 / (1.2 * 1e4));
  const double ts = 15.0;
  const auto spin_rate = [&](double spin, double t) {
    return t >= ts ? spin : spin / ts * (t - ts / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi * t / ts));
  };
  const Json& cells = summary["sections"]["spin"]["cells"];
  ASSERT_EQ(cells.items.size(), 12u);  // 3 spins × 2 stiffenings × 2 models
  for (const Json& cell : cells.items) {
    const double spin = extra(cell, "spin_rad_per_s");
    const bool stiffened = extra(cell, "stiffened") != 0.0;
    SCOPED_TRACE(cell["row"].text + " " + cell["column"].text);
    if (stiffened || spin < omega1) {
      // K + Ω²K_c (or Ωs below ω1): bounded, well inside the watch's bound.
      EXPECT_TRUE(cell["ok"].flag);
      EXPECT_EQ(cell["status"].text, "bounded");
      EXPECT_LT(cell["value"].number, 0.5 * 10.0);
      continue;
    }
    ASSERT_FALSE(cell["ok"].flag);
    ASSERT_EQ(cell["status"].text, "divergence");
    const double t = cell["time_s"].number;
    EXPECT_NEAR(extra(cell, "omega1_rad_per_s"), omega1, 1e-3 * omega1);
    EXPECT_NEAR(extra(cell, "spin_rate_at_detection_rad_per_s"), spin_rate(spin, t), 1e-9);
    // The stiffness K(1 − Ω²/ω1²) collapses as Ω(t) reaches ω1; the 0.5 L bound is passed once the
    // spin has gone beyond ω1 (the softened mode then grows exponentially), before Ts. The fitted rate
    // is positive and no faster than the instantaneous √(Ω² − ω1²) (Ω still rises through the window).
    EXPECT_LT(t, ts);
    const double omega = spin_rate(spin, t);
    EXPECT_GT(omega, omega1);
    EXPECT_LT(omega, 1.1 * omega1);
    EXPECT_GT(cell["value"].number, 0.0);  // a growth rate σ [1/s]
    EXPECT_LE(cell["value"].number, 1.05 * std::sqrt(omega * omega - omega1 * omega1));
  }
  // The nodal and modal stiffened runs agree (second method).
  EXPECT_LT(summary["sections"]["spin"]["numbers"]["nodal_modal_disagreement_stiffened_4"].number, 0.02);

  // BDF 3–5 on the undamped boom: the step size collapses (several times the steps of A-stable BDF 2).
  EXPECT_GT(summary["sections"]["bdf_order"]["numbers"]["step_ratio_order5_to_order2"].number, 3.0);
  // Index-1 drifts; Baumgarte's feedback holds the clamp better.
  const Json& drift = summary["sections"]["drift"]["numbers"];
  EXPECT_EQ(drift["cvode_max_drift_m"].number, 0.0);
  EXPECT_GT(drift["index1_max_drift_m"].number, 3.0 * drift["baumgarte_max_drift_m"].number);
  // The explicit limit falls as the mesh is refined (ω_max grows).
  const Json& explicit_numbers = summary["sections"]["explicit"]["numbers"];
  EXPECT_LT(explicit_numbers["smallest_stable_step_s"].number, 0.5 * explicit_numbers["largest_stable_step_s"].number);
}

TEST(CliStability, DroppedLoadSnapPeakAndFreeFallMatchTheHandDerivation) {
  TempDir dir;
  const Json summary = stability_summary(dir, "cases/dropped_load.toml");
  // Scene: m = 1.3e6 kg, k = 2e8 N/m, g = 9.81, lift d = 0.5 m, undamped wire, rigid boom on a fixed hub.
  const double m = 1.3e6, k = 2e8, g = 9.81, d = 0.5;
  const double s = m * g / k, omega = std::sqrt(k / m);
  const double hand_peak = k * (s + std::sqrt(s * s + 2.0 * g * (d - s) / (omega * omega)));
  const double free_fall = std::sqrt(2.0 * (d - s) / g);
  bool snap = false, slack = false;
  double elastic_peak = 0.0;
  for (const Json& cell : summary["sections"]["wire"]["cells"].items) {
    if (cell["row"].text == "rigid" && cell["status"].text == "snap load" && !snap) {
      snap = true;  // the first snap
      EXPECT_FALSE(cell["ok"].flag);
      EXPECT_NEAR(cell["value"].number, hand_peak, 0.01 * hand_peak);
      EXPECT_NEAR(cell["ratio_to_static"].number, hand_peak / (m * g), 0.01 * hand_peak / (m * g));
    }
    if (cell["row"].text == "rigid" && cell["status"].text == "wire slack" && !slack) {
      slack = true;  // released at rest above the taut length: slack from t = 0 for the free fall
      EXPECT_NEAR(cell["time_s"].number, 0.0, 1e-9);
      EXPECT_NEAR(cell["value"].number, free_fall, 0.01 * free_fall);
    }
    if (cell["row"].text == "nodal N=8" && cell["status"].text == "snap load" && elastic_peak == 0.0) {
      elastic_peak = cell["value"].number;
    }
  }
  EXPECT_TRUE(snap && slack);
  // The elastic boom is a softer spring in series with the wire: a lower snap peak.
  EXPECT_GT(elastic_peak, 0.0);
  EXPECT_LT(elastic_peak, hand_peak);

  // Root compression of the boom at 60°: (ρA L + m) g sin φ (statics of the boom), against π²EI/(4L²).
  const double compression = (1e4 * 120.0 + m) * g * std::sin(std::numbers::pi / 3.0);
  const double euler = std::numbers::pi * std::numbers::pi * 2.1e11 * 11.4 / (4.0 * 120.0 * 120.0);
  const Json& buckling = summary["sections"]["buckling"]["numbers"];
  EXPECT_NEAR(-buckling["root_axial_force_N"].number, compression, 0.02 * compression);
  EXPECT_NEAR(buckling["load_ratio"].number, compression / euler, 0.02 * compression / euler);
  // Compression softens the first bending mode: ω1² ≈ ω1,0² (1 − P/P_E) to first order.
  const double w0 = buckling["omega1_unstressed_rad_per_s"].number;
  const double w = buckling["omega1_prestressed_rad_per_s"].number;
  EXPECT_LT(w, w0);
  EXPECT_NEAR(w * w / (w0 * w0), 1.0 - compression / euler, 0.2 * compression / euler);
  EXPECT_FALSE(summary["sections"].members.empty());
}

TEST(CliStability, BadInputExitsTwoNamingTheProblem) {
  TempDir dir;
  const RunResult unknown = run_ffrf("stability '" + source_file("cases/spin_up_beam.toml") + "' --fast", dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--fast"), std::string::npos) << unknown.err;
  const RunResult missing = run_ffrf("stability '" + (dir / "no_such_scene.toml").string() + "'", dir.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no_such_scene.toml"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace ffrf::test
