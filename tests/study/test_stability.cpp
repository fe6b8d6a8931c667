// The stability experiments (study/stability.hpp) called directly with --quick settings (moved from
// the CLI test), asserting the physics against hand results: the unstiffened linear floating frame
// fails during the spin-up as Ω(t) approaches the first bending frequency ω1 = 1.8751²√(EI/(ρA L⁴))
// (its bending stiffness K(1 − Ω²/ω1²) goes to zero), the centrifugally stiffened runs stay bounded,
// BDF 3–5 need many more steps than BDF 2 on the undamped boom, the index-1 drift exceeds the
// stabilized one, the dropped load's snap peak is k(s + A) and its free fall lasts √(2(d − s)/g)
// (the scene file's hand derivation), and the root compression is (ρA L + m) g sin φ.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "study/stability.hpp"
#include "study_test_support.hpp"

namespace stability_test {

using namespace ffrf;

TEST(Stability, SpinUpUnstiffenedDivergesOnceTheSpinPassesTheFirstBendingFrequencyStiffenedStaysBounded) {
  const scene::Scene scene = test::scene_file("spin_up_beam.toml");
  const study::StabilityMap map = study::stability_map(scene, {true, {}});
  ASSERT_TRUE(map.spin && map.bdf_order && map.drift && map.explicit_steps);
  EXPECT_FALSE(map.wire || map.buckling) << "no cargo";
  // Scene: EI = 7e10 · 2e-7 N m², ρA = 1.2 kg/m, L = 10 m, spin-up over Ts = 15 s, divergence at 0.5 L.
  const double omega1 = 1.875104068711961 * 1.875104068711961 * std::sqrt(7e10 * 2e-7 / (1.2 * 1e4));
  const double ts = 15.0;
  const auto spin_rate = [&](double spin, double t) {
    return t >= ts ? spin : spin / ts * (t - ts / (2.0 * std::numbers::pi) * std::sin(2.0 * std::numbers::pi * t / ts));
  };
  const study::SpinStudy& spin = *map.spin;
  EXPECT_NEAR(spin.omega1, omega1, 1e-3 * omega1);
  ASSERT_EQ(spin.runs.size(), 12u);  // 3 spins × 2 stiffenings × 2 models
  for (const study::SpinRun& run : spin.runs) {
    SCOPED_TRACE(run.label() + ", spin " + std::to_string(run.spin));
    if (run.stiffened || run.spin < omega1) {
      // K + Ω²K_c (or Ωs below ω1): bounded, well inside the watch's bound.
      EXPECT_FALSE(run.failure);
      EXPECT_LT(run.max_deflection, 0.5 * 10.0);
      continue;
    }
    ASSERT_TRUE(run.failure);
    ASSERT_EQ(run.failure->kind, solve::FailureKind::divergence);
    const double t = run.failure->time;
    EXPECT_NEAR(run.spin_rate_at_failure, spin_rate(run.spin, t), 1e-9);
    // The stiffness K(1 − Ω²/ω1²) collapses as Ω(t) reaches ω1; the 0.5 L bound is passed once the
    // spin has gone beyond ω1, before Ts. The fitted rate is positive and no faster than the
    // instantaneous √(Ω² − ω1²) (Ω still rises through the window).
    EXPECT_LT(t, ts);
    const double omega = spin_rate(run.spin, t);
    EXPECT_GT(omega, omega1);
    EXPECT_LT(omega, 1.1 * omega1);
    EXPECT_GT(run.failure->value, 0.0);  // a growth rate σ [1/s]
    EXPECT_LE(run.failure->value, 1.05 * std::sqrt(omega * omega - omega1 * omega1));
  }
  // The nodal and modal stiffened runs agree (second method).
  EXPECT_LT(spin.agreement, 0.02);
  // BDF 3–5 on the undamped boom: the step size collapses (several times the steps of A-stable BDF 2).
  EXPECT_GT(map.bdf_order->step_ratio, 3.0);
  // Index-1 drifts; Baumgarte's feedback holds the clamp better; minimal coordinates have no constraint.
  using solve::Integrator;
  EXPECT_EQ(map.drift->max_drift(Integrator::cvode), 0.0);
  EXPECT_GT(map.drift->max_drift(Integrator::index1), 3.0 * map.drift->max_drift(Integrator::baumgarte));
  // The explicit limit falls as the mesh is refined (ω_max grows).
  double smallest = INFINITY, largest = 0.0;
  for (const study::ExplicitStabilityRow& row : map.explicit_steps->map.rows) {
    if (!row.ok()) continue;
    smallest = std::min(smallest, row.measured.stable_step);
    largest = std::max(largest, row.measured.stable_step);
  }
  EXPECT_LT(smallest, 0.5 * largest);
}

TEST(Stability, DroppedLoadSnapPeakAndFreeFallMatchTheHandDerivation) {
  const scene::Scene scene = test::scene_file("dropped_load.toml");
  const study::StabilityOptions quick{true, {}};
  const study::WireStudy wire = study::wire_study(scene, quick);
  // Scene: m = 1.3e6 kg, k = 2e8 N/m, g = 9.81, lift d = 0.5 m, undamped wire, rigid boom on a fixed hub.
  const double m = 1.3e6, k = 2e8, g = 9.81, d = 0.5;
  const double s = m * g / k, omega = std::sqrt(k / m);
  const double hand_peak = k * (s + std::sqrt(s * s + 2.0 * g * (d - s) / (omega * omega)));
  const double free_fall = std::sqrt(2.0 * (d - s) / g);
  EXPECT_NEAR(wire.hand_peak, hand_peak, 1e-9 * hand_peak);
  ASSERT_EQ(wire.runs.size(), 2u);
  const study::WireRun& rigid = wire.runs[0];
  const study::WireRun& elastic = wire.runs[1];
  ASSERT_TRUE(rigid.run && elastic.run);
  ASSERT_FALSE(rigid.snaps.empty());
  ASSERT_FALSE(rigid.slack.empty());
  EXPECT_NEAR(rigid.snaps.front().peak_tension, hand_peak, 0.01 * hand_peak);
  EXPECT_NEAR(rigid.snaps.front().ratio, hand_peak / (m * g), 0.01 * hand_peak / (m * g));
  // Released at rest above the taut length: slack from t = 0 for the free fall.
  EXPECT_NEAR(rigid.slack.front().start, 0.0, 1e-9);
  EXPECT_NEAR(rigid.slack.front().end - rigid.slack.front().start, free_fall, 0.01 * free_fall);
  // The elastic boom is a softer spring in series with the wire: a lower snap peak.
  ASSERT_FALSE(elastic.snaps.empty());
  EXPECT_LT(elastic.snaps.front().peak_tension, hand_peak);

  // Root compression of the boom at 60°: (ρA L + m) g sin φ (statics of the boom), against π²EI/(4L²).
  const study::BucklingStudy buckling = study::buckling_study(scene, quick);
  const double compression = (1e4 * 120.0 + m) * g * std::sin(std::numbers::pi / 3.0);
  const double euler = std::numbers::pi * std::numbers::pi * 2.1e11 * 11.4 / (4.0 * 120.0 * 120.0);
  EXPECT_NEAR(-buckling.axial_force, compression, 0.02 * compression);
  EXPECT_NEAR(buckling.load_ratio, compression / euler, 0.02 * compression / euler);
  // Compression softens the first bending mode: ω1² ≈ ω1,0² (1 − P/P_E) to first order.
  const double w0 = buckling.omega1_unstressed, w = buckling.omega1_prestressed;
  EXPECT_LT(w, w0);
  EXPECT_NEAR(w * w / (w0 * w0), 1.0 - compression / euler, 0.2 * compression / euler);
}

}  // namespace stability_test
