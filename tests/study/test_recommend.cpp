// The recommend study (study::recommend) called directly (moved from the CLI tests). Independent
// checks: the chosen model's error and the next cheaper one's against the tolerance (verification
// runs against the converged reference); the reasoning's boom frequencies against the modes
// analysis; the static tip deflection and Euler load against the cantilever formulas evaluated here
// from the scene's numbers; a very stiff boom is rigid; a wave near the boom's first period keeps
// that mode; the spin-up scene's unstiffened model fails by a named divergence; cost counted as
// RHS evaluations × state size, the ladder ranked by expected work.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "study/error_measure.hpp"
#include "study/modes.hpp"
#include "study/recommend.hpp"
#include "study_test_support.hpp"

namespace recommend_test {

using namespace ffrf;

const study::Candidate& chosen(const study::Recommendation& rec) { return rec.candidates.at(rec.chosen.value()); }

bool fails(const study::Candidate& c, double tolerance) {
  return c.status == study::CandidateStatus::solver_failure || c.error > tolerance;
}

TEST(Recommend, ReferenceSceneAtOnePercentChosenPassesNextCheaperFails) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::RecommendRequest request;
  request.duration = 40.0;
  const study::Recommendation rec = study::recommend(scene, request);
  ASSERT_TRUE(rec.chosen);
  const study::Candidate& c = chosen(rec);
  EXPECT_EQ(c.status, study::CandidateStatus::passed);
  EXPECT_LE(c.error, 0.01);
  ASSERT_TRUE(rec.next_cheaper);
  EXPECT_LT(*rec.next_cheaper, *rec.chosen);
  EXPECT_TRUE(fails(rec.candidates[*rec.next_cheaper], 0.01)) << study::to_string(rec.candidates[*rec.next_cheaper].status);
  // Cost is solver work, RHS evaluations × state size (2 × minimal coordinates), and the speed-up is the reference's over the chosen one's.
  EXPECT_DOUBLE_EQ(c.work(), static_cast<double>(c.rhs_evaluations) * c.state_size);
  EXPECT_NEAR(rec.work_speedup(), rec.reference.run.work() / c.work(), 1e-9 * rec.work_speedup());
  EXPECT_GT(rec.work_speedup(), 1.0);
  // No candidate that passed did less solver work (its integrator twins among them).
  for (const study::Candidate& t : rec.candidates) {
    if (t.status == study::CandidateStatus::passed) { EXPECT_LE(c.work(), t.work()) << t.label(); }
  }
  // The prestress is 5 % of the Euler load: the reasoning asks for static stiffening, and the
  // unstiffened twin of the chosen model is what it proves wrong.
  EXPECT_EQ(c.choice.stiffening.value_or(rec.reference_scene.boom.stiffening), scene::Stiffening::static_load);
  EXPECT_EQ(rec.reference_scene.boom.stiffening, scene::Stiffening::static_load);

  // Reasoning figures from the cantilever formulas, evaluated here from the scene's numbers.
  const double L = 120.0, EI = 2.1e11 * 11.4, rhoA = 1.0e4, g = 9.81, mc = 1.3e6, phi = std::numbers::pi / 3.0;
  const double delta = (mc * g * L * L * L / 3.0 + rhoA * g * std::pow(L, 4) / 8.0) * std::cos(phi) / EI;
  EXPECT_NEAR(rec.reasoning.static_tip_deflection, delta, 1e-9 * delta);
  EXPECT_NEAR(rec.reasoning.euler_load, std::numbers::pi * std::numbers::pi * EI / (4.0 * L * L), 1.0);
  EXPECT_NEAR(rec.reasoning.wave_frequency, 2.0 * std::numbers::pi / 10.0, 1e-12);
  EXPECT_EQ(rec.reasoning.dynamic_modes, 1);  // (0.628/3.78)²/(1 − ·) = 2.8 % > 1 %

  // The frequency figures are those of the modes analysis of the same boom.
  const study::ModesResult modes = study::solve_modes(scene.boom.mesh, fem::Boundary::clamped_free,
                                                      modal::EigenSolverKind::arpack,
                                                      static_cast<int>(rec.reasoning.modes.size()));
  ASSERT_EQ(rec.reasoning.modes.size(), modes.modes.size());
  for (std::size_t i = 0; i < modes.modes.size(); ++i) {
    EXPECT_NEAR(rec.reasoning.modes[i].angular_frequency, modes.modes[i].angular_frequency, 1e-9 * modes.modes[i].angular_frequency);
  }
}

// The recommendation is the passing candidate with the least solver work, RHS evaluations × state
// size, whatever the ladder's order: an explicit twin that passed with many evaluations (a stiff wire:
// the irregular Tp 8 s record, ARKODE 216 542 evaluations, 4.3× the reference's wall time) loses to its
// BDF twin, and to a larger model that did less work; a cheaper candidate that failed is not chosen.
TEST(Recommend, CheapestPassingCandidateIsTheLeastSolverWork) {
  study::Candidate explicit_twin;
  explicit_twin.choice.kind = scene::BoomKind::modal;
  explicit_twin.choice.modes = 2;
  explicit_twin.integrator = solve::Integrator::arkode;
  explicit_twin.status = study::CandidateStatus::passed;
  explicit_twin.error = 0.009;
  explicit_twin.rhs_evaluations = 216542;
  explicit_twin.state_size = 16;                  // work 3.46e6
  study::Candidate bdf_twin = explicit_twin;
  bdf_twin.integrator = solve::Integrator::cvode;
  bdf_twin.rhs_evaluations = 20000;               // work 3.2e5
  study::Candidate larger = bdf_twin;
  larger.choice.modes = 4;
  larger.state_size = 20;                         // work 4.0e5
  larger.error = 0.001;
  study::Candidate failed = bdf_twin;
  failed.choice.modes = 1;
  failed.status = study::CandidateStatus::failed;
  failed.error = 0.02;
  failed.rhs_evaluations = 100;
  std::vector<study::Candidate> ladder{failed, explicit_twin, bdf_twin, larger};
  EXPECT_EQ(study::cheapest_passing_candidate(ladder, 0.01), 2u);
  ladder[2].status = study::CandidateStatus::failed;
  ladder[2].error = 0.011;
  EXPECT_EQ(study::cheapest_passing_candidate(ladder, 0.01), 3u) << "4.0e5 < 3.46e6: the larger model";
  ladder[3].status = study::CandidateStatus::solver_failure;
  EXPECT_EQ(study::cheapest_passing_candidate(ladder, 0.01), 1u);
  ladder[1].status = study::CandidateStatus::failed;
  EXPECT_FALSE(study::cheapest_passing_candidate(ladder, 0.01).has_value());
}

// The ladder's order is the expected solver work: state size × expected RHS evaluations. BDF
// candidates rank by state size (their steps follow the excitation and the accuracy); an explicit
// twin costs more evaluations per step and ranks after its BDF twin; a static-mode model (k + 5
// coordinates) ties with the vibration-mode model and mesh of its size and goes first, its
// a-priori error being the smallest.
TEST(Recommend, LadderRanksByExpectedWorkWithStaticModeModelsInTheirPlace) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  const study::RecommendReasoning reasoning = study::reason_about(scene, 0.01, study::judged_outputs(scene));
  const std::vector<study::Candidate> ladder = study::candidate_ladder(scene, reasoning);
  const auto index = [&](scene::BoomKind kind, int modes, bool static_modes, int elements, solve::Integrator integrator) {
    for (std::size_t i = 0; i < ladder.size(); ++i) {
      const scene::BoomChoice& c = ladder[i].choice;
      if (c.kind == kind && ladder[i].integrator == integrator && c.stiffening.value_or(scene::Stiffening::none) == scene::Stiffening::none &&
          (kind != scene::BoomKind::modal || (c.modes == modes && c.static_modes == static_modes)) &&
          (kind != scene::BoomKind::nodal || c.elements == elements))
        return i;
    }
    ADD_FAILURE() << "not in the ladder";
    return ladder.size();
  };
  for (std::size_t i = 1; i < ladder.size(); ++i) EXPECT_LE(ladder[i - 1].expected_work, ladder[i].expected_work) << i;
  using scene::BoomKind;
  const auto cvode = solve::Integrator::cvode, arkode = solve::Integrator::arkode;
  // Static stiffening is required here, so the unstiffened variants are pruned but still ranked.
  const std::size_t k1_static = index(BoomKind::modal, 1, true, 0, cvode);
  const std::size_t k6 = index(BoomKind::modal, 6, false, 0, cvode);
  const std::size_t n2 = index(BoomKind::nodal, 0, false, 2, cvode);
  EXPECT_EQ(ladder[k1_static].expected_work, ladder[k6].expected_work) << "6 elastic coordinates each";
  EXPECT_LT(k1_static, k6);
  EXPECT_LT(k6, n2) << "no a-priori estimate for a mesh: after the models that have one";
  EXPECT_LT(index(BoomKind::modal, 5, false, 0, cvode), k1_static);
  EXPECT_LT(k1_static, index(BoomKind::modal, 2, true, 0, cvode));
  // The explicit twin of modal k = 2 (admitted: its step limit is above the output interval) after its BDF twin.
  EXPECT_LT(index(BoomKind::modal, 2, false, 0, cvode), index(BoomKind::modal, 2, false, 0, arkode));
}

TEST(Recommend, VeryStiffBoomIsRigid) {
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.boom.mesh.section.youngs_modulus = 2.1e15;
  study::RecommendRequest request;
  request.duration = 30.0;
  request.reference.max_levels = 2;
  const study::Recommendation rec = study::recommend(scene, request);
  ASSERT_TRUE(rec.chosen);
  EXPECT_EQ(chosen(rec).choice.kind, scene::BoomKind::rigid);
  EXPECT_LE(chosen(rec).error, 0.01);
  // ω1 = 3.78 · 100 rad/s: no mode is driven dynamically by the 10 s wave.
  EXPECT_EQ(rec.reasoning.dynamic_modes, 0);
  EXPECT_NEAR(rec.reasoning.modes.at(0).angular_frequency, 100.0 * 3.778, 0.01 * 377.8);
}

TEST(Recommend, WavePeriodNearTheBoomsFirstPeriodKeepsTheMode) {
  // The boom softened 3.6× (E = 5.8e10 Pa: ω1 = 3.78·√(5.8/21) = 1.99 rad/s, period 3.2 s) under a
  // 5 s wave (ω_w = 1.257 rad/s), which the hull passes on (its heave period is 5.9 s): mode 1 is
  // driven at r = 0.63, a quasi-static error r²/(1 − r²) = 0.66 ≫ 1 %, so no model may treat it
  // statically.
  scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  scene.wave->period = 5.0;
  scene.boom.mesh.section.youngs_modulus = 5.8e10;
  study::RecommendRequest request;
  request.duration = 30.0;
  const study::Recommendation rec = study::recommend(scene, request);
  const double omega1 = rec.reasoning.modes.at(0).angular_frequency;
  EXPECT_NEAR(omega1, 3.7779 * std::sqrt(5.8e10 / 2.1e11), 2e-3 * omega1);
  EXPECT_NEAR(rec.reasoning.wave_frequency, 2.0 * std::numbers::pi / 5.0, 1e-12);
  const double r = rec.reasoning.wave_frequency / omega1;
  EXPECT_GT(r * r / (1.0 - r * r), 0.5);
  EXPECT_GE(rec.reasoning.dynamic_modes, 1);
  // Every candidate that drops a dynamically driven mode is pruned, never run.
  for (const study::Candidate& c : rec.candidates) {
    const bool drops_modes = c.choice.kind == scene::BoomKind::rigid ||
                             (c.choice.kind == scene::BoomKind::modal && c.choice.modes < rec.reasoning.dynamic_modes);
    if (drops_modes) {
      EXPECT_EQ(c.status, study::CandidateStatus::pruned) << c.label();
    }
  }
  ASSERT_TRUE(rec.chosen);
  const study::Candidate& c = chosen(rec);
  EXPECT_EQ(c.status, study::CandidateStatus::passed);
  EXPECT_LE(c.error, 0.01);
  EXPECT_NE(c.choice.kind, scene::BoomKind::rigid);
  if (c.choice.kind == scene::BoomKind::modal) {
    EXPECT_GE(c.choice.modes, rec.reasoning.dynamic_modes);
  }
  ASSERT_TRUE(rec.next_cheaper);
  EXPECT_TRUE(fails(rec.candidates[*rec.next_cheaper], 0.01));
}

TEST(Recommend, SpinUpRequiresCentrifugalStiffening) {
  const scene::Scene scene = test::scene_file("spin_up_beam.toml");
  study::RecommendRequest request;
  request.duration = 14.0;
  request.reference.max_levels = 1;
  const study::Recommendation rec = study::recommend(scene, request);
  ASSERT_TRUE(rec.chosen);
  EXPECT_EQ(chosen(rec).choice.stiffening.value_or(rec.reference_scene.boom.stiffening), scene::Stiffening::centrifugal);
  EXPECT_LE(chosen(rec).error, 0.01);
  const double w1 = rec.reasoning.modes.at(0).angular_frequency;
  EXPECT_NEAR(rec.reasoning.centrifugal_softening, 16.0 / (w1 * w1), 1e-12);
  EXPECT_EQ(rec.reasoning.required_stiffening, scene::Stiffening::centrifugal);
  // The unstiffened linear model, when run, diverges (Ω = 4 > ω1 ≈ 3.8 rad/s): a named solver failure.
  ASSERT_TRUE(rec.next_cheaper);
  const study::Candidate& cheaper = rec.candidates[*rec.next_cheaper];
  EXPECT_EQ(cheaper.choice.stiffening.value_or(rec.reference_scene.boom.stiffening), scene::Stiffening::none);
  EXPECT_EQ(cheaper.status, study::CandidateStatus::solver_failure);
  EXPECT_NE(cheaper.failure.find("divergence"), std::string::npos) << cheaper.failure;
}

}  // namespace recommend_test
