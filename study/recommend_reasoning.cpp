// The physics that prunes `ffrf recommend`'s search (see recommend_reasoning.hpp).
#include "study/recommend_reasoning.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "scene/irregular_sea.hpp"
#include "scene/luffing_wires.hpp"
#include "study/error_measure.hpp"
#include "study/verdict.hpp"
#include "study/modes.hpp"
#include "fem/analytic_beam.hpp"

namespace ffrf::study {
namespace {

constexpr int reasoning_modes = 6;  // as many as `ffrf modes` lists by default for a clamped boom

bool contains(const std::vector<multibody::OutputChannel>& outputs, multibody::OutputChannel channel) {
  return std::find(outputs.begin(), outputs.end(), channel) != outputs.end();
}

scene::Stiffening combine(scene::Stiffening a, scene::Stiffening b) {
  const bool s = scene::has_static_stiffening(a) || scene::has_static_stiffening(b);
  const bool c = scene::has_centrifugal_stiffening(a) || scene::has_centrifugal_stiffening(b);
  if (s && c) return scene::Stiffening::both;
  if (s) return scene::Stiffening::static_load;
  return c ? scene::Stiffening::centrifugal : scene::Stiffening::none;
}

void excitation(const scene::Scene& scene, RecommendReasoning& r) {
  if (scene::has_waves(scene)) r.wave_frequency = 2.0 * std::numbers::pi / scene::shortest_wave_period(scene);
  if (scene.hub && scene.hub->motion != scene::HubMotion::fixed) r.spin_rate = std::abs(scene.hub->spin_rate);
  r.excitation_top = std::max(r.wave_frequency, r.spin_rate);
  std::string band;
  if (r.wave_frequency > 0.0 && scene.wave) {
    band = fmt::format("the wave (T = {:g} s) drives the crane at ω_w = {:.4g} rad/s", scene.wave->period, r.wave_frequency);
  } else if (r.wave_frequency > 0.0) {
    band = fmt::format("the irregular sea (characteristic period {:g} s) drives the crane up to its highest component "
                       "ω_w = {:.4g} rad/s",
                       scene::characteristic_wave_period(scene), r.wave_frequency);
  }
  if (r.spin_rate > 0.0) {
    band += fmt::format("{}the hub spins at up to Ω = {:.4g} rad/s", band.empty() ? "" : "; ", r.spin_rate);
  }
  r.statements.push_back(band.empty() ? "Excitation: none periodic (calm water, no spin): only the initial state moves the crane."
                                      : "Excitation band: " + band + ".");
}

void frequencies(const scene::Scene& scene, RecommendReasoning& r) {
  const fem::BeamMesh& mesh = scene.boom.mesh;
  const int dof = free_dof_count(mesh, fem::Boundary::clamped_free);
  const ModesResult modes =
      solve_modes(mesh, fem::Boundary::clamped_free, modal::EigenSolverKind::arpack, std::min(dof - 1, reasoning_modes));
  std::string list;
  for (const modal::ClassifiedMode& m : modes.modes) {
    r.modes.push_back({m.angular_frequency, std::string(fem::to_string(m.kind))});
    list += fmt::format("{}{:.4g} ({})", list.empty() ? "" : ", ", m.angular_frequency, fem::to_string(m.kind));
  }
  r.statements.push_back(fmt::format("Boom natural frequencies (clamped-free, N = {}, as `ffrf modes`): ω = {} rad/s.",
                                     mesh.element_count, list));
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    if (quasi_static_error(r.excitation_top, r.modes[i].angular_frequency) > r.tolerance) r.dynamic_modes = static_cast<int>(i) + 1;
  }
  if (r.excitation_top == 0.0) return;
  const double w1 = r.modes.front().angular_frequency;
  if (r.dynamic_modes == 0) {
    r.statements.push_back(fmt::format(
        "All modes lie far above the excitation: ω1/ω_e = {:.3g}, so a static treatment of mode 1 errs by only {:.2g} "
        "(≤ τ = {:g}): static correction suffices, no vibration mode must be kept.",
        w1 / r.excitation_top, quasi_static_error(r.excitation_top, w1), r.tolerance));
  } else {
    const double w = r.modes[static_cast<std::size_t>(r.dynamic_modes) - 1].angular_frequency;
    r.statements.push_back(fmt::format(
        "Mode {} (ω = {:.4g} rad/s, ω/ω_e = {:.3g}) is not quasi-static: treating it statically errs by r²/(1 − r²) = {:.2g} "
        "> τ = {:g}, so modal models keep k ≥ {} vibration modes.",
        r.dynamic_modes, w, w / r.excitation_top, quasi_static_error(r.excitation_top, w), r.tolerance, r.dynamic_modes));
  }
}

void loads(const scene::Scene& scene, const std::vector<multibody::OutputChannel>& outputs, RecommendReasoning& r) {
  const fem::BeamMesh& mesh = scene.boom.mesh;
  const double L = mesh.length, EI = mesh.section.bending_rigidity(), rhoA = mesh.section.mass_per_length;
  const double g = scene.environment.gravity, phi = scene::boom_angle_at_rest(scene);
  const double cargo_weight = scene.cargo ? scene.cargo->mass * g : 0.0;
  const bool pinned = scene.boom.mount && scene.boom.mount->pinned && scene.luffing;
  if (pinned) {
    // Pinned at the heel, held at the tip by the luffing wires: the span sags as a simply supported
    // beam, 5qL⁴/(384EI) at mid-length, and the wires' pull along the boom adds to its compression.
    const scene::LuffingGeometry luffing = scene::luffing_geometry(scene);
    const Eigen::Vector2d axis(std::cos(phi), std::sin(phi));
    const double wire_compression = -luffing.total_tension * ((luffing.a_frame - luffing.boom_point) / luffing.length).dot(axis);
    r.static_tip_deflection = 5.0 * rhoA * g * std::pow(L, 4) / 384.0 * std::cos(phi) / EI;
    r.axial_load = (rhoA * g * L + cargo_weight) * std::sin(phi) + wire_compression;
    r.euler_load = *fem::euler_buckling_load(scene.boom.mesh, fem::Boundary::pinned_pinned);
  } else {
    r.static_tip_deflection = (cargo_weight * L * L * L / 3.0 + rhoA * g * std::pow(L, 4) / 8.0) * std::cos(phi) / EI;
    r.axial_load = (rhoA * g * L + cargo_weight) * std::sin(phi);
    r.euler_load = *fem::euler_buckling_load(scene.boom.mesh, fem::Boundary::clamped_free);
  }
  if (contains(outputs, multibody::OutputChannel::tip_deflection)) {
    r.rigid_error = 1.0;
    r.statements.push_back("Rigid boom: the tip deflection is a chosen output and a rigid boom has none (error 100 %).");
  } else if (scene::has_waves(scene)) {
    const double rms_heave = std::sqrt(scene::sea_components(scene).variance());
    r.rigid_error = r.static_tip_deflection * std::cos(phi) / rms_heave;
    r.statements.push_back(fmt::format(
        "Rigid boom: it misses the static deflection δ = {} = {:.3g} m under {}; its vertical part δ cos φ = {:.3g} m against the cargo's RMS heave {} = {:.3g} m estimates its error "
        "at {:.2g} (τ = {:g}).",
        pinned ? "5q⊥L⁴/(384EI) (the span between the heel pin and the luffing wires)" : "F⊥L³/(3EI) + q⊥L⁴/(8EI)",
        r.static_tip_deflection, pinned ? "its own weight" : "the cargo and its own weight", r.static_tip_deflection * std::cos(phi),
        scene.wave ? "H/(2√2)" : "(the sea's RMS elevation √m0)", rms_heave, r.rigid_error, r.tolerance));
  } else {
    r.rigid_error = std::numeric_limits<double>::quiet_NaN();
    r.statements.push_back("Rigid boom: no wave to scale its error by; only its verification run can tell.");
  }
  // Geometric stiffening.
  scene::Stiffening required = scene::Stiffening::none;
  if (r.axial_load > 0.0) {
    const double amplification = r.axial_load < r.euler_load ? r.axial_load / (r.euler_load - r.axial_load)
                                                             : std::numeric_limits<double>::infinity();
    r.static_stiffening_effect = (std::isfinite(r.rigid_error) ? std::min(r.rigid_error, 1.0e3) : 1.0) * amplification;
    if (contains(outputs, multibody::OutputChannel::boom_peak_stress)) {
      // The peak fibre stress |N|/A + |M|c/I: the prestress amplifies its bending part by P/(P_E − P)
      // (the span's qL²/8 of a pinned boom, the root's of a clamped one).
      const double q_perp = rhoA * g * std::cos(phi);
      const double moment = pinned ? q_perp * L * L / 8.0 : (cargo_weight * std::cos(phi) + 0.5 * q_perp * L) * L;
      const double bending = moment * scene.boom.fibre_distance / mesh.section.second_moment;
      const double membrane = r.axial_load / mesh.section.area;
      const double stress_effect = amplification * bending / (bending + membrane);
      r.statements.push_back(fmt::format(
          "Peak fibre stress: its bending part {:.3g} MPa of {:.3g} MPa grows by the prestress's P/(P_E − P): about {:.2g}.",
          bending * 1e-6, (bending + membrane) * 1e-6, stress_effect));
      r.static_stiffening_effect = std::max(r.static_stiffening_effect, stress_effect);
    }
    const bool needed = r.static_stiffening_effect > r.tolerance;
    if (needed) required = scene::Stiffening::static_load;
    r.statements.push_back(fmt::format(
        "Buckling: the boom carries P = {:.3g} N in compression against its Euler load {} = {:.3g} N (P/P_E = {:.3g}); "
        "the prestress changes the deflection by P/(P_E − P) = {:.2g}, the outputs by about {:.2g}: static stiffening is {}.",
        r.axial_load, pinned ? "π²EI/L²" : "π²EI/(4L²)", r.euler_load, r.axial_load / r.euler_load, amplification,
        r.static_stiffening_effect,
        needed ? "needed" : "not needed"));
  }
  if (r.spin_rate > 0.0) {
    const double w1 = r.modes.front().angular_frequency;
    r.centrifugal_softening = r.spin_rate * r.spin_rate / (w1 * w1);
    const bool needed = r.centrifugal_softening > r.tolerance;
    if (needed) required = combine(required, scene::Stiffening::centrifugal);
    r.statements.push_back(fmt::format(
        "Spin: without centrifugal stiffening the linear boom softens to ω1² − Ω², by Ω²/ω1² = {:.3g}{}: centrifugal "
        "stiffening is {}.",
        r.centrifugal_softening, r.spin_rate >= w1 ? fmt::format(" (Ω = {:.3g} ≥ ω1 = {:.4g} rad/s: it diverges)", r.spin_rate, w1) : "",
        needed ? "needed" : "not needed"));
  }
  r.required_stiffening = required;
  r.reference_stiffening = combine(required, scene.boom.stiffening);
}

}  // namespace

double quasi_static_error(double excitation, double angular_frequency) {
  if (angular_frequency <= 0.0) return std::numeric_limits<double>::infinity();
  const double r2 = (excitation / angular_frequency) * (excitation / angular_frequency);
  return r2 < 1.0 ? r2 / (1.0 - r2) : std::numeric_limits<double>::infinity();
}

double missing_flexibility(const scene::Scene& scene, const std::vector<BoomMode>& modes, int k) {
  const fem::BeamMesh& mesh = scene.boom.mesh;
  const double m = mesh.total_mass(), L = mesh.length, EI = mesh.section.bending_rigidity();
  double carried = 0.0;
  for (int i = 0; i < k && i < static_cast<int>(modes.size()); ++i) {
    const BoomMode& mode = modes[static_cast<std::size_t>(i)];
    if (mode.kind != "bending") continue;
    carried += 12.0 * EI / (mode.angular_frequency * mode.angular_frequency * m * L * L * L);
  }
  return std::max(0.0, 1.0 - carried);
}

RecommendReasoning reason_about(const scene::Scene& scene, double tolerance,
                                const std::vector<multibody::OutputChannel>& outputs) {
  RecommendReasoning r;
  r.tolerance = tolerance;
  excitation(scene, r);
  frequencies(scene, r);
  loads(scene, outputs, r);
  r.relative_tolerance = model_choice_rtol(tolerance);
  r.statements.push_back(fmt::format(
      "Integrator: BDF (CVODE) at rtol = {:g}, the model-choice rtol of τ (four decades below it: a BDF run's global error "
      "reaches ~100× its rtol), so the model, not the integrator, decides each candidate's error; compare and sweep name "
      "their cheapest model at the same rtol.",
      r.relative_tolerance));
  return r;
}

scene::Stiffening physics_stiffening(const scene::Scene& scene, double tolerance) {
  return reason_about(scene, tolerance, judged_outputs(scene)).reference_stiffening;
}

}  // namespace ffrf::study
