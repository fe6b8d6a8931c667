// Integrators as formulation × solver pairs against independent facts:
//  * every valid pair reproduces the crane response of the minimal-coordinate CVODE reference at
//    rtol 1e-10 (a second method) within its own tolerance; the names in use before the split are
//    aliases of distinct pairs; a pair that is not implemented is refused naming the valid ones;
//  * one callback guard: a C++ exception thrown inside a right-hand side or residual becomes a
//    named failure (model error, with the message and the time), never a crash, for every pair;
//  * a failing set-up call is named (an invalid tolerance injected into the library call path).
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "solve/integrator_table.hpp"
#include "crane_test_support.hpp"

namespace integrator_choices_test {

using namespace ffrf;
using solve::Formulation;
using solve::Integrator;
using solve::Solver;

// The reference scene, nodal N = 2, at static equilibrium.
struct Crane {
  scene::Scene scene = test::reference_scene();
  std::unique_ptr<multibody::CraneEquations> equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 2, 0, false});
  Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
};

multibody::RunSettings settings(Integrator kind, double duration, double tolerance) {
  multibody::RunSettings s;
  s.kind = kind;
  s.relative_tolerance = s.absolute_tolerance = tolerance;
  s.duration = duration;
  s.output_interval = 0.05;
  if (kind.solver == Solver::generalized_alpha) s.fixed_step = 0.005;
  return s;
}

TEST(IntegratorChoices, NamesAreDistinctPairsAndInvalidPairsAreRefused) {
  int count = 0;
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    ++count;
    EXPECT_EQ(solve::parse_integrator(entry.name), entry.choice) << entry.name;
    EXPECT_EQ(solve::to_string(entry.choice), entry.name);
    EXPECT_EQ(solve::integrator(entry.choice.formulation, entry.choice.solver), entry.choice);
    for (const solve::IntegratorEntry& other : solve::integrator_table()) {
      if (&other != &entry) {
        EXPECT_FALSE(other.choice == entry.choice) << entry.name << " and " << other.name;
      }
    }
  }
  EXPECT_EQ(count, 7) << "cvode, arkode, ida, generalized-alpha, index1, baumgarte, projection";
  EXPECT_EQ(solve::Integrator::ida, (Integrator{Formulation::index2, Solver::bdf}));
  EXPECT_EQ(solve::Integrator::arkode, (Integrator{Formulation::minimal, Solver::explicit_rk}));
  try {
    solve::integrator(Formulation::minimal, Solver::generalized_alpha);
    ADD_FAILURE() << "minimal × generalized-alpha is not implemented";
  } catch (const solve::InvalidIntegrator& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("minimal with solver generalized-alpha"), std::string::npos) << message;
    EXPECT_NE(message.find("index2 × bdf (ida)"), std::string::npos) << message;
  }
  Crane crane;  // the dispatch refuses it too, as a set-up failure
  auto s = settings(Integrator{Formulation::index2, Solver::explicit_rk}, 1.0, 1e-6);
  try {
    multibody::simulate(*crane.equations, crane.z0, s);
    ADD_FAILURE() << "index2 × explicit-rk must be refused";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), solve::FailureKind::setup);
    EXPECT_NE(failure.cause().find("valid pairs"), std::string::npos) << failure.what();
  }
}

TEST(IntegratorChoices, EveryValidPairReproducesTheMinimalCoordinateReference) {
  Crane crane;
  const double duration = 10.0;
  const auto reference = multibody::simulate(*crane.equations, crane.z0, settings(Integrator::cvode, duration, 1e-10));
  double scale = 0.0;  // the motion being compared: cargo heave and hull pitch about their start
  for (const auto& o : reference.samples) scale = std::max(scale, std::abs(o.cargo.y() - reference.samples[0].cargo.y()));
  ASSERT_GT(scale, 1e-3) << "the wave moves the cargo";
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    // BDF and explicit RK at rtol 1e-8: their global error stays within ~100 rtol of the motion;
    // generalized-α at h = 5 ms: second order, (h ω)² ≈ 1e-5 of the motion for ω ≈ 0.6 rad/s.
    const bool fixed = entry.choice.solver == Solver::generalized_alpha;
    const double tolerance = fixed ? 1e-5 : 1e-6;
    const auto run = multibody::simulate(*crane.equations, crane.z0, settings(entry.choice, duration, 1e-8));
    ASSERT_EQ(run.samples.size(), reference.samples.size()) << entry.name;
    double heave = 0.0, pitch = 0.0, pitch_scale = 0.0;
    for (std::size_t k = 0; k < run.samples.size(); ++k) {
      heave = std::max(heave, std::abs(run.samples[k].cargo.y() - reference.samples[k].cargo.y()));
      pitch = std::max(pitch, std::abs(run.samples[k].hull.z() - reference.samples[k].hull.z()));
      pitch_scale = std::max(pitch_scale, std::abs(reference.samples[k].hull.z() - reference.samples[0].hull.z()));
    }
    std::printf("%-18s %-11s × %-17s cargo heave %.3e, hull pitch %.3e (relative to the motion); %ld steps\n",
                std::string(entry.name).c_str(), std::string(solve::to_string(entry.choice.formulation)).c_str(),
                std::string(solve::to_string(entry.choice.solver)).c_str(), heave / scale, pitch / pitch_scale,
                run.stats.steps);
    EXPECT_LT(heave / scale, tolerance) << entry.name;
    EXPECT_LT(pitch / pitch_scale, tolerance) << entry.name;
  }
}

// The crane's equations, throwing a std::logic_error from the dynamics once t passes `from`.
class ThrowingEquations final : public multibody::CraneEquations {
 public:
  ThrowingEquations(multibody::CraneEquations& inner, double from) : inner_(inner), from_(from) {}
  int minimal_size() const override { return inner_.minimal_size(); }
  Eigen::VectorXd initial_guess() const override { return inner_.initial_guess(); }
  void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) override {
    check(t);
    inner_.minimal_accelerations(t, z, z_dot, z_ddot);
  }
  void static_residual(ConstRef z, Ref residual) override { inner_.static_residual(z, residual); }
  void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) override {
    inner_.minimal_generalized_forces(t, z, z_dot, forces);
  }
  Eigen::VectorXd static_residual_scale() const override { return inner_.static_residual_scale(); }
  Eigen::VectorXd coordinate_scale() const override { return inner_.coordinate_scale(); }
  multibody::CraneOutputs minimal_outputs(double t, ConstRef z, ConstRef z_dot) override { return inner_.minimal_outputs(t, z, z_dot); }
  int full_size() const override { return inner_.full_size(); }
  void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const override { inner_.full_from_minimal(t, z, z_dot, q, v); }
  void full_mass_times(ConstRef q, ConstRef a, Ref out) override { inner_.full_mass_times(q, a, out); }
  void full_forces(double t, ConstRef q, ConstRef v, Ref out) override {
    check(t);
    inner_.full_forces(t, q, v, out);
  }
  void constraint(double t, ConstRef q, Ref c) const override { inner_.constraint(t, q, c); }
  void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const override { inner_.constraint_jacobian(q, jacobian); }
  void constraint_time_derivative(double t, Ref c_t) const override { inner_.constraint_time_derivative(t, c_t); }
  void constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const override {
    inner_.constraint_rate_terms(t, q, v, gamma);
  }
  void full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) override { inner_.full_mass_matrix(q, mass); }
  multibody::CraneOutputs full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) override {
    return inner_.full_outputs(t, q, v, lambda);
  }
  int constraint_count() const override { return inner_.constraint_count(); }
  int wire_count() const override { return inner_.wire_count(); }
  int hoist_wire() const override { return inner_.hoist_wire(); }
  std::string wire_name(int wire) const override { return inner_.wire_name(wire); }
  void wire_stretches_minimal(double t, ConstRef z, Ref stretch) override { inner_.wire_stretches_minimal(t, z, stretch); }
  void wire_stretches_full(double t, ConstRef q, Ref stretch) override { inner_.wire_stretches_full(t, q, stretch); }
  multibody::WireRole wire_role(int wire) const override { return inner_.wire_role(wire); }
  const multibody::CraneLayout& layout() const override { return inner_.layout(); }
  std::string body_name(int body) const override { return inner_.body_name(body); }
  int cargo_body() const override { return inner_.cargo_body(); }
  int elastic_size() const override { return inner_.elastic_size(); }

 private:
  void check(double t) const {
    if (t > from_) throw std::logic_error("injected fault in the dynamics");
  }
  multibody::CraneEquations& inner_;
  double from_;
};

TEST(IntegratorChoices, AnExceptionInsideACallbackIsANamedFailureForEveryPair) {
  Crane crane;
  ThrowingEquations throwing(*crane.equations, 0.3);
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    try {
      multibody::simulate(throwing, crane.z0, settings(entry.choice, 1.0, 1e-6));
      ADD_FAILURE() << entry.name << ": the injected fault must end the run";
    } catch (const solve::SolverFailure& failure) {
      EXPECT_EQ(failure.kind(), solve::FailureKind::model_error) << entry.name << ": " << failure.what();
      EXPECT_NE(failure.cause().find("injected fault"), std::string::npos) << entry.name << ": " << failure.what();
      EXPECT_GE(failure.time(), 0.25) << entry.name;
      EXPECT_LE(failure.time(), 0.35 + 1e-9) << entry.name << ": within an output interval of the fault";
      ASSERT_NE(multibody::partial_run(failure), nullptr) << entry.name;
      EXPECT_GE(multibody::partial_run(failure)->samples.size(), 6u) << entry.name << ": the samples before the fault are kept";
    }
  }
}

TEST(IntegratorChoices, AFailingSetUpCallIsNamed) {
  Crane crane;
  for (const auto& [kind, call] : {std::pair{Integrator::cvode, "CVodeSVtolerances returned CV_ILL_INPUT"},
                                   std::pair{Integrator::index1, "CVodeSVtolerances returned CV_ILL_INPUT"},
                                   std::pair{Integrator::ida, "IDASVtolerances returned IDA_ILL_INPUT"},
                                   std::pair{Integrator::arkode, "ERKStepSVtolerances returned ARK_ILL_INPUT"}}) {
    auto s = settings(kind, 1.0, 1e-6);
    s.relative_tolerance = -1e-6;  // past the study's checks, straight into the library call
    try {
      multibody::simulate(*crane.equations, crane.z0, s);
      ADD_FAILURE() << solve::to_string(kind) << ": a negative tolerance must be refused";
    } catch (const solve::SolverFailure& failure) {
      EXPECT_EQ(failure.kind(), solve::FailureKind::setup) << failure.what();
      EXPECT_EQ(failure.cause().rfind(call, 0), 0u) << failure.what();
      EXPECT_NE(failure.cause().find("< 0 illegal"), std::string::npos) << "SUNDIALS' own message: " << failure.what();
    }
  }
  auto s = settings(Integrator::cvode, 1.0, 1e-6);
  s.max_order = 0;
  try {
    multibody::simulate(*crane.equations, crane.z0, s);
    ADD_FAILURE() << "BDF order 0 must be refused";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.cause().rfind("CVodeSetMaxOrd returned CV_ILL_INPUT", 0), 0u) << failure.what();
  }
}

}  // namespace integrator_choices_test
