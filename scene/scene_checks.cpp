// Cross-key physics checks of a scene (see scene_checks.hpp for the list and the references).
#include "scene/scene_checks.hpp"

#include "scene/a_frame.hpp"
#include "scene/luffing_wires.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "scene/scene_key.hpp"
#include "sea/wave_field.hpp"
#include "hydro/sea_steepness.hpp"
#include "scene/irregular_sea.hpp"

namespace ffrf::scene {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kOnSurface = 1e-9;  // relative slack for "on" a face of a box

// Findings collected in order.
class Findings {
 public:
  void error(std::vector<std::string> keys, std::string message) { add(true, std::move(keys), std::move(message)); }
  void warning(std::vector<std::string> keys, std::string message) { add(false, std::move(keys), std::move(message)); }
  std::vector<SceneFinding> take() { return std::move(found_); }

 private:
  void add(bool is_error, std::vector<std::string> keys, std::string message) {
    found_.push_back({is_error, std::move(keys), std::move(message)});
  }
  std::vector<SceneFinding> found_;
};

bool within(double value, double lower, double upper) {
  const double slack = kOnSurface * std::max({1.0, std::abs(lower), std::abs(upper)});
  return value >= lower - slack && value <= upper + slack;
}

// The cargo hook on or inside its box, and its radius of gyration within the box's reach.
void check_cargo(const Cargo& cargo, Findings& found) {
  const double half_length = 0.5 * cargo.length, half_height = 0.5 * cargo.height;
  if (!within(cargo.hook_x, -half_length, half_length)) {
    found.error({scene_key("cargo.hook_x"), scene_key("cargo.length")},
                fmt::format("the hook C lies off the cargo box (length {:g} m): it must be on or inside it (valid "
                            "range [{:g}, {:g}] m)",
                            cargo.length, -half_length, half_length));
  }
  if (!within(cargo.hook_y, -half_height, half_height)) {
    found.error({scene_key("cargo.hook_y"), scene_key("cargo.height")},
                fmt::format("the hook C lies off the cargo box (height {:g} m): it must be on or inside it (valid "
                            "range [{:g}, {:g}] m)",
                            cargo.height, -half_height, half_height));
  }
  const double reach = 0.5 * std::hypot(cargo.length, cargo.height);
  if (!cargo.radius_of_gyration_derived && cargo.pitch_radius_of_gyration > reach * (1.0 + kOnSurface)) {
    found.error({scene_key("cargo.pitch_radius_of_gyration"), scene_key("cargo.length"), scene_key("cargo.height")},
                fmt::format("a radius of gyration cannot exceed the distance from G2 to the box's corners, {:.4g} m "
                            "(valid range [0.001, {:.4g}] m)",
                            reach, reach));
  }
}

// G1, the boom root and the hull's radius of gyration against the box; false when G1 is outside
// (the hydrostatic checks would then mean nothing).
bool check_hull_geometry(const Scene& scene, Findings& found) {
  const Hull& hull = *scene.hull;
  const BoomMount& mount = *scene.boom.mount;
  bool inside = true;
  if (hull.g1_above_keel >= hull.depth) {
    found.error({scene_key("hull.g1_above_keel"), scene_key("hull.depth")},
                fmt::format("G1 must lie inside the hull, below the deck (valid range [0, {:g}) m: the hull depth)",
                            hull.depth));
    inside = false;
  }
  const double half = 0.5 * hull.length;
  if (std::abs(hull.g1_aft_of_mid_length) > half) {
    found.error({scene_key("hull.g1_aft_of_mid_length"), scene_key("hull.length")},
                fmt::format("G1 must lie inside the hull, within half its length of mid-length (valid range [{:g}, "
                            "{:g}] m)",
                            -half, half));
    inside = false;
  }
  // The box relative to G1 (hull frame): x from the stern to the bow, y from the keel to the deck.
  const double stern = hull.g1_aft_of_mid_length - half, bow = hull.g1_aft_of_mid_length + half;
  const double keel = -hull.g1_above_keel, deck = hull.depth - hull.g1_above_keel;
  if (!within(mount.root_x, stern, bow)) {
    found.error({scene_key("boom.root_x"), scene_key("hull.length"), scene_key("hull.g1_aft_of_mid_length")},
                fmt::format("the boom root B must stand on the hull, between its stern and bow (valid range [{:g}, "
                            "{:g}] m from G1)",
                            stern, bow));
  }
  const double pedestal = 0.5 * hull.length;
  if (!within(mount.root_y, keel, deck + pedestal)) {
    found.error({scene_key("boom.root_y"), scene_key("hull.depth"), scene_key("hull.g1_above_keel")},
                fmt::format("the boom root B must lie on the hull, between the keel and a crane pedestal of at most "
                            "half the hull length above the deck (valid range [{:g}, {:g}] m from G1)",
                            keel, deck + pedestal));
  }
  if (inside) {
    const double reach = std::max(std::hypot(stern, keel), std::max(std::hypot(stern, deck),
                                                                    std::max(std::hypot(bow, keel), std::hypot(bow, deck))));
    if (hull.pitch_radius_of_gyration > reach * (1.0 + kOnSurface)) {
      found.error({scene_key("hull.pitch_radius_of_gyration"), scene_key("hull.length"), scene_key("hull.depth")},
                  fmt::format("a radius of gyration cannot exceed the distance from G1 to the hull's farthest corner, "
                              "{:.4g} m (valid range [0.1, {:.4g}] m)",
                              reach, reach));
    }
  }
  return inside;
}

// Buoyancy, depth, stability and trim of the loaded hull at rest; the cargo above the water.
void check_hydrostatics(const Scene& scene, Findings& found) {
  const Hull& hull = *scene.hull;
  const Cargo& cargo = *scene.cargo;
  const double rho = scene.environment.water_density;
  const double boom_mass = scene.boom.mesh.total_mass();
  const double a_frame_mass = scene.a_frame ? scene.a_frame->mass : 0.0;  // (an A-frame rigid with the hull is in hull.mass)
  const double total = hull.mass + boom_mass + cargo.mass + a_frame_mass;
  const double capacity = rho * hull.length * hull.width * hull.depth;
  if (total >= capacity) {
    std::vector<std::string> keys{scene_key("hull.mass"), scene_key("boom.mass_per_length"), scene_key("cargo.mass")};
    if (scene.a_frame) keys.push_back(scene_key("a_frame.mass"));
    for (const char* key : {scene_key("hull.length"), scene_key("hull.width"), scene_key("hull.depth")}) keys.push_back(key);
    found.error(std::move(keys),
                fmt::format("the loaded crane would sink: hull {:.6g} t + boom {:.6g} t + cargo {:.6g} t{} = {:.6g} t "
                            "is not less than the buoyancy of the fully submerged hull ρ·L·B·D = {:.6g} t",
                            hull.mass / 1e3, boom_mass / 1e3, cargo.mass / 1e3,
                            scene.a_frame ? fmt::format(" + A-frame {:.6g} t", a_frame_mass / 1e3) : std::string(), total / 1e3,
                            capacity / 1e3));
    return;
  }
  if (hull.mass < 0.01 * (boom_mass + cargo.mass + a_frame_mass)) {
    found.warning({scene_key("hull.mass"), scene_key("boom.mass_per_length"), scene_key("cargo.mass")},
                  fmt::format("the hull ({:.6g} t) is lighter than 1 % of the boom and cargo{} it carries ({:.6g} t): a "
                              "mass in t written as kg?",
                              hull.mass / 1e3, scene.a_frame ? " and A-frame" : "", (boom_mass + cargo.mass + a_frame_mass) / 1e3));
  }
  const RestingHydrostatics rest = resting_hydrostatics(scene);
  if (scene.environment.water_depth <= rest.draft) {
    found.error({scene_key("environment.water_depth"), scene_key("hull.mass"), scene_key("cargo.mass")},
                fmt::format("the hull would ground: its draft at rest is {:.4g} m (valid range ({:.4g}, 11000] m or "
                            "inf)",
                            rest.draft, rest.draft));
  }
  if (rest.metacentric_height <= 0.0) {
    const double kb = 0.5 * rest.draft, bm = hull.length * hull.length / (12.0 * rest.draft);
    found.error({scene_key("hull.g1_above_keel"), scene_key("hull.length"), scene_key("boom.angle"), scene_key("cargo.mass")},
                fmt::format("the loaded crane is unstable in pitch: GM_L = KB + BM_L − KG = {:.4g} + {:.4g} − {:.4g} = "
                            "{:.4g} m ≤ 0 with the cargo hanging at the boom tip (valid: GM_L > 0; lower the load or "
                            "the boom, or lengthen the hull)",
                            kb, bm, kb + bm - rest.metacentric_height, rest.metacentric_height));
    return;
  }
  const double freeboard = hull.depth - rest.draft;
  if (rest.deck_sinkage >= freeboard) {
    const bool bow = rest.trim > 0.0;
    found.error({scene_key("cargo.mass"), scene_key("boom.root_x"), scene_key("boom.angle"), scene_key("hull.g1_aft_of_mid_length")},
                fmt::format("the deck would be under water at rest: the load moment {:.4g} t m about mid-length needs "
                            "a trim of θ = M/(Δ·GM_L) = {:.3g} deg {} to balance (linear hydrostatics, GM_L = {:.4g} "
                            "m), but the {} deck edge reaches the water at {:.3g} deg (freeboard {:.4g} m over half "
                            "the length, {:g} m); lighten the load, shorten the outreach or move G1 to balance it",
                            std::abs(rest.load_moment) / 1e3, std::abs(rest.trim) / kDegree, bow ? "bow down" : "stern down",
                            rest.metacentric_height, bow ? "bow" : "stern",
                            std::atan(freeboard / (0.5 * hull.length)) / kDegree, freeboard, 0.5 * hull.length));
    return;
  }
  if (rest.cargo_bottom < 0.0) {
    found.error({scene_key("wire.unstretched_length"), scene_key("cargo.height"), scene_key("boom.angle"), scene_key("boom.length")},
                fmt::format("the cargo would hang in the water at rest: its bottom {:.4g} m below the still water "
                            "level (the model has no water forces on the cargo); shorten the wire to at most {:.4g} m "
                            "or raise the boom",
                            -rest.cargo_bottom, std::max(0.0, scene.wire->unstretched_length + rest.cargo_bottom)));
  }
}

// Breaking and the validity of linear (Airy) theory.
void check_wave(const Scene& scene, Findings& found) {
  const Wave& wave = *scene.wave;
  const double g = scene.environment.gravity, depth = scene.environment.water_depth;
  if (wave.height <= 0.0 || g <= 0.0) return;
  const double omega = 2.0 * std::numbers::pi / wave.period;
  const double k = sea::WaveField::wave_number_from_dispersion(omega, depth, g);
  const double wavelength = 2.0 * std::numbers::pi / k;
  if (wave.height >= wavelength / 7.0) {
    found.error({scene_key("wave.height"), scene_key("wave.period")},
                fmt::format("the wave breaks: its steepness H/λ = {:.3g} is not below 1/7 (Michell's limit) for the "
                            "wavelength λ = {:.4g} m of T = {:g} s (valid range [0, {:.4g}) m)",
                            wave.height / wavelength, wavelength, wave.period, wavelength / 7.0));
  }
  if (std::isinf(depth)) return;
  if (wave.height >= 0.78 * depth) {
    found.error({scene_key("wave.height"), scene_key("environment.water_depth")},
                fmt::format("the wave breaks in this depth: H/d = {:.3g} is not below 0.78 (depth-limited breaking) "
                            "(valid range [0, {:.4g}) m)",
                            wave.height / depth, 0.78 * depth));
    return;
  }
  const double ursell = wave.height * wavelength * wavelength / (depth * depth * depth);
  if (k * depth < std::numbers::pi / 10.0 || ursell > 26.0) {
    found.warning({scene_key("environment.water_depth"), scene_key("wave.height"), scene_key("wave.period")},
                  fmt::format("shallow water for this wave: kd = {:.3g} (shallow below π/10), Ursell number H λ²/d³ = "
                              "{:.3g} (nonlinear above 26): linear (Airy) wave theory is outside its range, the "
                              "motions are indicative only",
                              k * depth, ursell));
  }
}

// An irregular sea: below DNV-RP-C205's mean-steepness limit (§3.5.5: Sp = 2π Hs / (g Tp²) ≤ 1/15
// for Tp ≤ 8 s, 1/25 for Tp ≥ 15 s, linear between), every user component below Michell's limit
// (H/λ = a k / π < 1/7), and a warning when the synthesized sea repeats within the record.
void check_sea(const Scene& scene, Findings& found) {
  const IrregularSea& sea = *scene.sea;
  const double g = scene.environment.gravity, depth = scene.environment.water_depth;
  if (g <= 0.0) return;
  if (sea.spectrum == SeaSpectrum::components) {
    for (std::size_t n = 0; n < sea.component_frequencies.size() && n < sea.component_amplitudes.size(); ++n) {
      const double k = sea::WaveField::wave_number_from_dispersion(sea.component_frequencies[n], depth, g);
      const double limit = std::numbers::pi / (7.0 * k);
      if (sea.component_amplitudes[n] >= limit) {
        found.error({scene_key("wave.component_amplitudes"), scene_key("wave.component_frequencies")},
                    fmt::format("component {} breaks: amplitude {:g} m at ω = {:g} rad/s (λ = {:.4g} m) is a steepness "
                                "H/λ = {:.3g}, not below 1/7 (valid range [0, {:.4g}) m)",
                                n + 1, sea.component_amplitudes[n], sea.component_frequencies[n],
                                2.0 * std::numbers::pi / k, sea.component_amplitudes[n] * k / std::numbers::pi, limit));
        return;
      }
    }
    return;
  }
  if (!(sea.peak_period > 0.0 && sea.significant_height >= 0.0)) return;  // out of range: the schema names it
  const hydro::SeaSteepness steep = hydro::sea_steepness(sea.significant_height, sea.peak_period, g);
  if (steep.breaking()) {
    found.error({scene_key("wave.significant_height"), scene_key("wave.peak_period")},
                fmt::format("the sea is too steep: Hs/λp = 2π Hs/(g Tp²) = {:.3g} exceeds DNV-RP-C205's limit {:.4g} "
                            "for Tp = {:g} s (λp = {:.4g} m; valid range (0, {:.4g}] m)",
                            steep.steepness, steep.limit, sea.peak_period, steep.peak_wavelength, steep.largest_height()));
  }
  if (!std::isinf(depth) && 1.86 * sea.significant_height >= 0.78 * depth) {
    found.warning({scene_key("wave.significant_height"), scene_key("environment.water_depth")},
                  fmt::format("the largest waves of a 3-hour storm (about 1.86 Hs = {:.3g} m) reach the depth-limited "
                              "breaking height 0.78 d = {:.3g} m: linear waves are indicative only",
                              1.86 * sea.significant_height, 0.78 * depth));
  }
  if (sea.component_count > 0) {
    double lo = sea.frequency_min, hi = sea.frequency_max;
    if (lo == 0.0 && hi == 0.0) {
      const hydro::FrequencyBand band = hydro::energy_band(sea_spectrum(sea), 1e-3);
      lo = band.lower;
      hi = band.upper;
    }
    const double repeat = 2.0 * std::numbers::pi * sea.component_count / (hi - lo);
    if (repeat < scene.simulation.duration * (1.0 - 1e-12)) {
      found.warning({scene_key("wave.components"), scene_key("simulation.duration")},
                    fmt::format("the synthesized sea repeats after 2π/Δω = {:.6g} s, shorter than the record "
                                "simulation.duration = {:g} s: statistics over the record count the same waves again; "
                                "use wave.components >= {:.0f} (or 0: Δω = 2π / duration)",
                                repeat, scene.simulation.duration,
                                std::ceil(scene.simulation.duration * (hi - lo) / (2.0 * std::numbers::pi))));
    }
  }
}

}  // namespace

RestingHydrostatics resting_hydrostatics(const Scene& scene) {
  const Hull& hull = *scene.hull;
  const BoomMount& mount = *scene.boom.mount;
  const Cargo& cargo = *scene.cargo;
  const Wire& wire = *scene.wire;
  const double rho = scene.environment.water_density, g = scene.environment.gravity;
  const double boom_length = scene.boom.mesh.length;
  const double boom_mass = scene.boom.mesh.total_mass();
  // An A-frame pinned to the deck is a mass of its own, centred halfway up (rigid with the hull, it is in hull.mass).
  const double a_frame_mass = scene.a_frame ? scene.a_frame->mass : 0.0;
  const double a_frame_x = scene.a_frame ? 0.5 * (scene.a_frame->pin_x + scene.luffing->a_frame_x) : 0.0;
  const double a_frame_y = scene.a_frame ? 0.5 * (scene.a_frame->pin_y + scene.luffing->a_frame_y) : 0.0;
  RestingHydrostatics rest;
  rest.displacement = hull.mass + boom_mass + cargo.mass + a_frame_mass;
  rest.draft = rest.displacement / (rho * hull.length * hull.width);
  // Heights above the keel (even keel); the cargo's weight acts at the boom tip it hangs from.
  const double sin_angle = std::sin(mount.angle), cos_angle = std::cos(mount.angle);
  const double root_height = hull.g1_above_keel + mount.root_y;
  const double tip_height = root_height + boom_length * sin_angle;
  const double centre_of_gravity = (hull.mass * hull.g1_above_keel +
                                    boom_mass * (root_height + 0.5 * boom_length * sin_angle) + cargo.mass * tip_height +
                                    a_frame_mass * (hull.g1_above_keel + a_frame_y)) /
                                   rest.displacement;
  rest.metacentric_height = 0.5 * rest.draft + hull.length * hull.length / (12.0 * rest.draft) - centre_of_gravity;
  // Lever arms forward of mid-length (x = g1_aft_of_mid_length from G1).
  const double mid = hull.g1_aft_of_mid_length;
  const double tip_x = mount.root_x + boom_length * cos_angle;
  rest.load_moment = hull.mass * (0.0 - mid) + boom_mass * (mount.root_x + 0.5 * boom_length * cos_angle - mid) +
                     cargo.mass * (tip_x - mid) + a_frame_mass * (a_frame_x - mid);
  if (rest.metacentric_height <= 0.0) return rest;
  rest.trim = rest.load_moment / (rest.displacement * rest.metacentric_height);
  rest.deck_sinkage = 0.5 * hull.length * std::abs(std::tan(std::clamp(rest.trim, -1.5, 1.5)));
  // The cargo's lowest point: below the tip by the stretched wire, the hook and half its box.
  const double tip_above_water = tip_height - rest.draft - (tip_x - mid) * rest.trim;
  const double stretch = g > 0.0 ? cargo.mass * g / wire.stiffness : 0.0;
  rest.cargo_bottom = tip_above_water - wire.unstretched_length - stretch - cargo.hook_y - 0.5 * cargo.height;
  return rest;
}

std::vector<SceneFinding> physics_findings(const Scene& scene) {
  Findings found;
  if (scene.cargo) check_cargo(*scene.cargo, found);
  if (scene.is_crane() && scene.boom.mount && scene.cargo && scene.wire) {
    const bool inside = check_hull_geometry(scene, found);
    if (scene.environment.gravity <= 0.0) {
      found.error({scene_key("environment.gravity"), scene_key("hull.mass")},
                  "a floating hull needs gravity: its buoyancy ρ g V holds it up (valid range (0, 30] m/s^2 with a "
                  "[hull])");
    } else if (inside) {
      check_hydrostatics(scene, found);
    }
    if (scene.mooring.surge_stiffness <= 0.0) {
      found.error({scene_key("mooring.surge_stiffness"), scene_key("hull.mass")},
                  "surge has no restoring force: nothing but a mooring spring holds the hull in surge, so its static "
                  "equilibrium is undetermined; add [mooring] with surge_stiffness > 0 (the reference crane has 5e5 "
                  "N/m) (valid range (0, 1e+10] N/m with a [hull])");
    }
    if (scene.wave) check_wave(scene, found);
    if (scene.sea) check_sea(scene, found);
    if (scene.luffing) {
      std::vector<SceneFinding> findings = luffing_findings(scene);
      const bool luffing_holds = std::none_of(findings.begin(), findings.end(), [](const SceneFinding& f) { return f.error; });
      if (luffing_holds && scene.a_frame && scene.backstay) {
        for (SceneFinding& finding : a_frame_findings(scene)) findings.push_back(std::move(finding));
      }
      for (SceneFinding& finding : findings) {
        if (finding.error) {
          found.error(std::move(finding.keys), std::move(finding.message));
        } else {
          found.warning(std::move(finding.keys), std::move(finding.message));
        }
      }
    }
  }
  const Simulation& simulation = scene.simulation;
  if (simulation.output_interval > simulation.duration) {
    found.error({scene_key("simulation.output_interval"), scene_key("simulation.duration")},
                fmt::format("longer than simulation.duration = {:g} s (valid range [1e-05, {:g}] s)", simulation.duration,
                            simulation.duration));
  } else if (simulation.duration / simulation.output_interval > max_output_samples) {
    found.error({scene_key("simulation.output_interval"), scene_key("simulation.duration")},
                fmt::format("{:.4g} output samples over simulation.duration = {:g} s, more than the limit of {:g} "
                            "(valid range [{:.4g}, {:g}] s)",
                            simulation.duration / simulation.output_interval, simulation.duration, max_output_samples,
                            simulation.duration / max_output_samples, simulation.duration));
  }
  return found.take();
}

}  // namespace ffrf::scene
