// The scene schema table: every scene key declared once — name, unit (dimension), range, default,
// help — with the sections that hold them. scene/scene_schema.cpp reads it (the loader, `ffrf check`
// and docs/scenes.md come from it), and scene_key() (scene/scene_key.hpp) checks the keys the scene's
// code names against it at compile time. A header so that the check can see it; nothing else
// includes it.
#pragma once

#include <array>
#include <limits>
#include <string_view>

#include "scene/scene_schema.hpp"

namespace ffrf::scene::schema_table {


constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// Physical ranges: what a floating crane (or a beam on a hub) can plausibly have, not only what the
// equations accept, so that a unit slip (210 Pa for 210 GPa, 12600 kg for 12600 t) or an overflow
// (1e308) is named here instead of ending in a solver. [a, b] includes the ends, above() excludes a.
constexpr Range between(double lower, double upper) { return {{lower, true}, {upper, true}}; }
constexpr Range above(double lower, double upper) { return {{lower, false}, {upper, true}}; }
constexpr Range kFraction{{0.0, true}, {1.0, false}};  // damping ratios below critical
constexpr Range kAny{};  // choice and text keys

constexpr KeySpec required(std::string_view name, Dimension dimension, Range range, std::string_view help,
                           std::string_view display_unit = {}) {
  return {name, ValueKind::number, dimension, range, Presence::required, 0.0, {}, {}, help, display_unit};
}
constexpr KeySpec crane_required(std::string_view name, Dimension dimension, Range range, std::string_view help,
                                 std::string_view display_unit = {}) {
  return {name, ValueKind::number, dimension, range, Presence::crane_required, 0.0, {}, {}, help, display_unit};
}
constexpr KeySpec defaulted(std::string_view name, Dimension dimension, Range range, double value,
                            std::string_view help, std::string_view display_unit = {}) {
  return {name, ValueKind::number, dimension, range, Presence::defaulted, value, {}, {}, help, display_unit};
}
constexpr KeySpec optional(std::string_view name, Dimension dimension, Range range, std::string_view help,
                           std::string_view display_unit = {}) {
  return {name, ValueKind::number, dimension, range, Presence::optional, 0.0, {}, {}, help, display_unit};
}
constexpr KeySpec one_of(std::string_view group, std::string_view name, Dimension dimension, Range range,
                         std::string_view help) {
  return {name, ValueKind::number, dimension, range, Presence::one_of, 0.0, {}, {}, help, {}, false, group};
}
constexpr KeySpec choice(std::string_view name, std::string_view choices, std::string_view default_text,
                         std::string_view help) {
  return {name, ValueKind::choice, Dimension::ratio, kAny, Presence::defaulted, 0.0, default_text, choices, help};
}
constexpr KeySpec text(std::string_view name, std::string_view help) {
  return {name, ValueKind::text, Dimension::ratio, kAny, Presence::optional, 0.0, {}, {}, help};
}
constexpr KeySpec integer(std::string_view name, Range range, double value, std::string_view help) {
  return {name, ValueKind::integer, Dimension::ratio, range, Presence::defaulted, value, {}, {}, help};
}
constexpr KeySpec number_list(std::string_view name, Dimension dimension, Range range, std::string_view help) {
  return {name, ValueKind::number_list, dimension, range, Presence::optional, 0.0, {}, {}, help};
}
constexpr KeySpec with_infinity(KeySpec key) {
  key.allow_infinity = true;
  return key;
}

using enum Dimension;

inline constexpr std::array kSections{
    SectionSpec{"scene", SectionRole::optional, "What the scene is: a name and a description for reports."},
    SectionSpec{"boom", SectionRole::required,
                "The elastic boom: an Euler–Bernoulli beam of uniform equivalent section, meshed with N frame "
                "elements. The only section of a single-beam scene such as cases/cantilever.toml."},
    SectionSpec{"hull", SectionRole::crane,
                "Crane hull G1: a rigid box in surge, heave and pitch. Hull frame: x forward (toward the bow, "
                "where the boom overhangs), y up, origin at G1."},
    SectionSpec{"hub", SectionRole::optional,
                "A rigid hub on a fixed axis normal to the plane, instead of a floating hull: the boom is clamped to "
                "it at radius hub.radius, and the hub is held or turned by a prescribed rotation θ(t) (a driving "
                "constraint). [cargo] and [wire] are optional with a hub (both or neither). Excludes [hull]."},
    SectionSpec{"cargo", SectionRole::crane, "Cargo G2: a rigid box in surge, heave and pitch, hanging on the wire."},
    SectionSpec{"wire", SectionRole::crane,
                "Wire rope from the boom tip A′ to the hook C: axial spring–damper, tension only."},
    SectionSpec{"luffing", SectionRole::optional,
                "Luffing wires of a boom pinned at its heel (boom.heel = \"pinned\"): tension-only elastic ropes from the "
                "top of the A-frame, a point fixed on the hull, to a point on the boom (its tip by default). They hold "
                "the boom up; the boom's angle at rest follows from their stretch. Only with a pinned heel."},
    SectionSpec{"a_frame", SectionRole::optional,
                "The A-frame as a rigid body pinned to the deck at its foot and held by the [backstay] wires, instead of "
                "rigid with the hull: the luffing wires pull its top (luffing.a_frame_x, luffing.a_frame_y) towards the "
                "boom, the backstays towards the deck aft, and it rocks on its pin between them. Its mass sits halfway "
                "between the pin and the top (a frame of uniform legs). Only with [luffing]; needs [backstay]."},
    SectionSpec{"backstay", SectionRole::optional,
                "Backstay wires from the A-frame's top to a deck point: tension-only elastic ropes that hold the "
                "[a_frame] against the luffing wires' pull. Only with [a_frame]."},
    SectionSpec{"environment", SectionRole::optional, "Sea water and gravity."},
    SectionSpec{"wave", SectionRole::optional,
                "Waves, ramped in over the first periods: a regular Airy wave (`spectrum = \"regular\"`, height and "
                "period) or a long-crested irregular sea: a JONSWAP or Pierson–Moskowitz spectrum (significant height, "
                "peak period) synthesized with random phases from `seed`, or user components. The components lie on "
                "ω_n = n Δω with Δω = 2π / simulation.duration unless `components` asks for another count, so the sea "
                "does not repeat within the record (a warning when it does). Leave the section out for calm water."},
    SectionSpec{"radiation", SectionRole::optional,
                "Linear radiation with constant coefficients in the hull frame at G1: added mass as multiples of "
                "the displaced mass (surge, heave) or of the hull's pitch inertia I55, damping as fractions of "
                "critical. Leave the section out for no radiation."},
    SectionSpec{"bem", SectionRole::optional,
                "Hull hydrodynamics from WAMIT output files (.1 added mass and damping, .3 excitation, .hst "
                "hydrostatics) or a Capytaine NetCDF dataset of the same hull, referred to G1: radiation by constant "
                "A(ω_c), B(ω_c), the Cummins convolution or its state-space fit; excitation by the incident-wave "
                "pressure (Froude–Krylov) or the BEM file (Froude–Krylov + diffraction). Excludes [radiation]. "
                "docs/hydrodynamics.md §6."},
    SectionSpec{"hull_damping", SectionRole::optional,
                "Damping added to the hull's equations in surge, heave and pitch at G1, beside [radiation] or [bem] "
                "(viscous and skin-friction damping that potential flow leaves out): linear, F = −b v, and "
                "quadratic, F = −b_q |v| v, per degree of freedom. The linearisation (`ffrf rao`, natural modes) "
                "keeps the linear part only: quadratic damping has none about rest. docs/hydrodynamics.md §6.2."},
    SectionSpec{"mooring", SectionRole::optional, "Linear mooring springs on the hull."},
    SectionSpec{"simulation", SectionRole::optional, "Time span and output of `ffrf run`."},
};

inline constexpr std::array kKeys{
    // [scene]
    text("scene.name", "Short name shown in reports."),
    text("scene.description", "One-line description of the scene."),
    // [boom]
    required("boom.length", length, between(0.1, 1000.0), "Boom length L from the root B to the tip A′."),
    required("boom.youngs_modulus", pressure, between(1e9, 1.5e12),
             "Young's modulus E of the equivalent section (1 GPa: polymer composites; 210 GPa: steel).", "GPa"),
    required("boom.area", area, between(1e-6, 100.0), "Cross-section area A (axial rigidity EA)."),
    required("boom.second_moment", second_moment, between(1e-14, 1e4),
             "Second moment of area I about the axis normal to the plane (bending rigidity EI)."),
    one_of("boom mass", "boom.mass_per_length", mass_per_length, between(1e-3, 1e6),
           "Mass per unit length ρA. Give exactly one of boom.mass_per_length and boom.density."),
    one_of("boom mass", "boom.density", density, between(100.0, 25000.0),
           "Material density ρ; the mass per length is ρ·A. Give exactly one of boom.mass_per_length and "
           "boom.density."),
    integer("boom.elements", between(1.0, 10000.0), 16.0,
            "Number N of beam finite elements (`--elements` overrides it)."),
    choice("boom.boundary", "clamped-free|free-free|pinned-pinned", "clamped-free",
           "Boundary condition for `ffrf modes` (`--boundary` overrides it). The coupled crane always clamps "
           "the root to the hull (the floating-frame reference condition)."),
    crane_required("boom.angle", angle, Range{{0.0, false}, {kPi / 2.0, false}},
                   "Boom angle above the hull's x axis (counter-clockwise), with its unit: \"60 deg\".", "deg"),
    crane_required("boom.root_x", length, between(-1000.0, 1000.0),
                   "x of the boom root B relative to G1, hull frame; B must lie over the hull (between its ends)."),
    crane_required("boom.root_y", length, between(-1000.0, 1000.0),
                   "y of the boom root B relative to G1, hull frame; B must lie between the keel and half the hull "
                   "length above the deck (a crane pedestal)."),
    choice("boom.heel", "clamped|pinned", "clamped",
           "The boom's heel joint on the hull at B: clamped (the boom turns with the hull at boom.angle: the source "
           "paper's model) or pinned (a revolute joint: the boom is free to luff and is held by the [luffing] wires, "
           "as floating cranes are built)."),
    defaulted("boom.damping_ratio", ratio, kFraction, 0.0,
              "Structural damping of the boom: fraction of critical in its first bending mode as supported (clamped-free; "
              "pinned-pinned for a pinned heel, the luffing wires holding the tip)."),
    choice("boom.damping", "stiffness-proportional|rayleigh", "stiffness-proportional",
           "The structural damping's form, the same operator in nodal and modal coordinates: stiffness-proportional "
           "(βK: boom.damping_ratio in the first mode, more in higher ones) or rayleigh (αM + βK: boom.damping_ratio in "
           "the first two modes, less between them, more above)."),
    choice("boom.stiffening", "none|static|centrifugal|both", "none",
           "Geometric (stress) stiffening of the boom: static = from the reference axial force of self-weight "
           "and cargo (compression softens), centrifugal = from the frame's angular velocity, updated during the "
           "run; both; none = the linear floating-frame model (`--stiffening` overrides it)."),
    optional("boom.fibre_distance", length, between(1e-4, 100.0),
             "Distance c from the boom's axis to its extreme fibres, for the fibre stresses N/A ± M c/I along the boom. "
             "Default: sqrt(I/A), the section whose area sits in two flanges at ±c (a lattice boom's chords)."),
    optional("boom.allowable_stress", pressure, between(1e6, 5e9),
             "Allowable stress of the boom's extreme fibre (a yield stress over its safety factor, e.g. \"235 MPa\"): the "
             "boom's stress utilisation is the peak fibre stress over this; `ffrf operability` judges it, and requires it "
             "for a pinned boom.",
             "MPa"),
    // [hull]
    required("hull.mass", mass, between(1e3, 1e9), "Hull mass without the boom.", "t"),
    required("hull.pitch_radius_of_gyration", length, between(0.1, 1000.0),
             "Radius of gyration of the hull for pitch about G1; at most the distance from G1 to the farthest "
             "corner of the box."),
    required("hull.length", length, between(1.0, 1000.0), "Length of the box hull (x)."),
    required("hull.width", length, between(1.0, 1000.0), "Width (beam) of the box hull, normal to the plane."),
    required("hull.depth", length, between(0.5, 100.0), "Depth of the box hull, keel to deck."),
    required("hull.g1_above_keel", length, between(0.0, 100.0), "Height of G1 above the keel; below the deck."),
    required("hull.g1_aft_of_mid_length", length, between(-500.0, 500.0),
             "Distance of G1 aft of the hull's mid-length (< 0: forward); within half the hull length."),
    // [hub]
    defaulted("hub.radius", length, between(0.0, 1000.0), 0.0,
              "Distance from the hub's axis to the boom root B, along the boom axis."),
    defaulted("hub.angle", angle, between(-2.0 * kPi, 2.0 * kPi), 0.0,
              "Angle of the hub and the boom above the x axis at t = 0, with its unit: \"30 deg\".", "deg"),
    choice("hub.motion", "fixed|spin-up|constant-spin", "fixed",
           "Prescribed rotation: fixed = held at hub.angle; spin-up = θ(t) = (Ωs/Ts)[t²/2 + (Ts/2π)²(cos(2πt/Ts) − 1)] "
           "for t < Ts, then Ωs (t − Ts/2) (Simo & Vu-Quoc 1986); constant-spin = Ωs t from rest."),
    defaulted("hub.spin_rate", angular_velocity, between(-1000.0, 1000.0), 0.0,
              "Final spin rate Ωs of spin-up and constant-spin."),
    defaulted("hub.spin_up_time", time, between(0.01, 1e5), 15.0, "Spin-up time Ts."),
    // [cargo]
    required("cargo.mass", mass, between(1.0, 1e8), "Cargo mass.", "t"),
    required("cargo.length", length, between(0.01, 500.0), "Length of the cargo box (x)."),
    required("cargo.height", length, between(0.01, 500.0), "Height of the cargo box (y)."),
    required("cargo.hook_x", length, between(-500.0, 500.0),
             "x of the hook C relative to G2, cargo frame; C must lie on or inside the box."),
    required("cargo.hook_y", length, between(-500.0, 500.0),
             "y of the hook C relative to G2, cargo frame; C must lie on or inside the box."),
    optional("cargo.pitch_radius_of_gyration", length, between(0.001, 500.0),
             "Radius of gyration for pitch about G2, at most half the box diagonal. Default: the uniform box's "
             "√((l² + h²)/12)."),
    // [wire]
    required("wire.unstretched_length", length, between(0.01, 5000.0), "Unstretched length L0 of the wire rope."),
    required("wire.stiffness", stiffness, between(1.0, 1e12), "Axial stiffness EA/L0 of the wire rope."),
    defaulted("wire.damping_ratio", ratio, kFraction, 0.0,
              "Axial damping as a fraction of critical for the cargo mass on the wire stiffness."),
    // [luffing]
    required("luffing.a_frame_x", length, between(-1000.0, 1000.0),
             "x of the A-frame top (where the luffing wires leave the hull) relative to G1, hull frame."),
    required("luffing.a_frame_y", length, between(-1000.0, 1000.0),
             "y of the A-frame top relative to G1, hull frame; above the boom's heel."),
    required("luffing.stiffness", stiffness, between(1.0, 1e12),
             "Axial stiffness of each luffing wire between the A-frame and the boom, EA/L; of one part of line when "
             "luffing.parts > 1 (the tackle's is luffing.parts times it)."),
    integer("luffing.wires", between(1.0, 4.0), 1.0,
            "Number of parallel luffing wires, each of luffing.stiffness (times luffing.parts when reeved)."),
    integer("luffing.parts", between(1.0, 24.0), 1.0,
            "Parts of line in each luffing wire's tackle (reeving between the A-frame's and the boom's sheave blocks): "
            "the tackle is luffing.parts times as stiff as one part and each part carries 1/luffing.parts of its pull "
            "(output luffing_line_pull_N)."),
    optional("luffing.attachment", length, between(0.0, 1000.0),
             "Distance along the boom from the heel B to the wires' boom point; at most boom.length. Default: the tip."),
    optional("luffing.unstretched_length", length, between(0.01, 5000.0),
             "Unstretched block-to-block length of each luffing wire. Default: the length that holds the rigid boom, and the cargo at "
             "its tip, at boom.angle on the level hull."),
    defaulted("luffing.damping_ratio", ratio, kFraction, 0.0,
              "Axial damping of each wire as a fraction of critical for the boom's inertia about its heel on the "
              "wires' rotational stiffness."),
    // [a_frame]
    required("a_frame.pin_x", length, between(-1000.0, 1000.0),
             "x of the A-frame's foot pin on the deck relative to G1, hull frame."),
    required("a_frame.pin_y", length, between(-1000.0, 1000.0),
             "y of the A-frame's foot pin relative to G1, hull frame; below the A-frame top."),
    required("a_frame.mass", mass, between(1.0, 1e8),
             "Mass of the A-frame, besides hull.mass (an A-frame rigid with the hull, without [a_frame], is part of hull.mass).", "t"),
    optional("a_frame.radius_of_gyration", length, between(0.001, 500.0),
             "Radius of gyration of the A-frame about its centre of mass, for its rotation in the plane. Default: a "
             "uniform bar's from the pin to the top, |top − pin|/√12."),
    // [backstay]
    required("backstay.deck_x", length, between(-1000.0, 1000.0),
             "x of the backstays' deck point relative to G1, hull frame; on the side of the A-frame away from the boom."),
    required("backstay.deck_y", length, between(-1000.0, 1000.0), "y of the backstays' deck point relative to G1, hull frame."),
    required("backstay.stiffness", stiffness, between(1.0, 1e12), "Axial stiffness EA/L of each backstay wire."),
    integer("backstay.wires", between(1.0, 4.0), 1.0, "Number of parallel backstay wires, each of backstay.stiffness."),
    optional("backstay.unstretched_length", length, between(0.01, 5000.0),
             "Unstretched length of each backstay. Default: the length that holds the A-frame at its built pose against "
             "the luffing wires' pull at rest (the rigid boom and the cargo at boom.angle on the level hull) and its own "
             "weight."),
    defaulted("backstay.damping_ratio", ratio, kFraction, 0.0,
              "Axial damping of each backstay as a fraction of critical for the A-frame's inertia about its pin on the "
              "backstays' rotational stiffness."),
    // [environment]
    defaulted("environment.water_density", density, between(800.0, 1500.0), 1025.0, "Sea-water density ρ."),
    defaulted("environment.gravity", acceleration, between(0.0, 30.0), 9.81,
              "Gravitational acceleration g (0: none; a floating hull needs it)."),
    with_infinity(defaulted("environment.water_depth", length, between(0.5, 11000.0), kInf,
                            "Water depth, more than the hull's draft; `inf` (or \"inf\") is deep water.")),
    // [wave]
    choice("wave.spectrum", "regular|jonswap|pierson-moskowitz|components", "regular",
           "regular: one Airy wave (height, period); jonswap, pierson-moskowitz: an irregular sea from the spectrum "
           "(significant_height, peak_period; JONSWAP also peak_enhancement, sigma_below, sigma_above) with random "
           "phases; components: the user's component_frequencies, component_amplitudes, component_phases."),
    optional("wave.height", length, between(0.0, 30.0),
             "Regular wave: height H, trough to crest (required with spectrum = regular); below the breaking limits "
             "H/λ < 1/7 and H < 0.78 × water depth."),
    optional("wave.period", time, between(1.0, 40.0), "Regular wave: period T (required with spectrum = regular)."),
    choice("wave.direction", "following|head", "following",
           "following: the waves travel +x (the boom overhangs the bow at +x); head: they travel −x."),
    defaulted("wave.ramp_periods", ratio, between(0.0, 100.0), 2.0,
              "The waves are ramped in over this many periods: T (regular), Tp (spectra) or the longest component "
              "period (components)."),
    optional("wave.significant_height", length, above(0.0, 30.0),
             "Irregular sea: significant wave height Hs = 4 √m0 (required with jonswap and pierson-moskowitz); the "
             "mean steepness Hs/λp must stay below DNV-RP-C205's limit (1/15 for Tp ≤ 8 s, 1/25 for Tp ≥ 15 s)."),
    optional("wave.peak_period", time, between(1.0, 40.0),
             "Irregular sea: spectral peak period Tp = 2π/ωp (required with jonswap and pierson-moskowitz)."),
    defaulted("wave.peak_enhancement", ratio, between(1.0, 20.0), 3.3,
              "JONSWAP peak-enhancement factor γ (1: Pierson–Moskowitz; 3.3: the mean JONSWAP sea)."),
    defaulted("wave.sigma_below", ratio, above(0.0, 0.5), 0.07, "JONSWAP spectral width σa for ω ≤ ωp."),
    defaulted("wave.sigma_above", ratio, above(0.0, 0.5), 0.09, "JONSWAP spectral width σb for ω > ωp."),
    integer("wave.seed", between(0.0, 2147483647.0), 1.0,
            "Random seed of the phases (and amplitudes): the same seed gives the same sea on any machine, thread "
            "or process count; another seed another realisation."),
    integer("wave.components", between(0.0, 2e6), 0.0,
            "Number of spectral components over the band (0: Δω = 2π / simulation.duration, the coarsest step "
            "that does not repeat within the record; a count that makes Δω coarser is warned about)."),
    optional("wave.frequency_min", angular_velocity, between(0.0, 100.0),
             "Lowest component frequency ω [rad/s] (default: the band holding all but 0.1 % of the variance)."),
    optional("wave.frequency_max", angular_velocity, above(0.0, 100.0),
             "Highest component frequency ω [rad/s] (default: the band holding all but 0.1 % of the variance)."),
    choice("wave.amplitudes", "deterministic|rayleigh", "deterministic",
           "deterministic: a_n = √(2 S(ω_n) Δω); rayleigh: a_n = √(2 S(ω_n) Δω E_n) with E_n unit exponential "
           "(a Gaussian sea also in its energy)."),
    choice("wave.kinematics", "precomputed|exact", "precomputed",
           "Irregular seas: precomputed evaluates the incident wave once per record (Taylor patches at the hull's "
           "sides, FFT in time, interpolated within wave.kinematics_tolerance; deep water and the spectral component "
           "grid only, else exact); exact sums every component in every hull-load evaluation (the reference)."),
    defaulted("wave.kinematics_tolerance", length, between(1e-9, 1e-2), 1e-5,
              "Precomputed kinematics: the largest error of the recorded incident wave (elevation units) inside the "
              "recorded region; the hull load's error is a few ρ g B times it per edge."),
    defaulted("wave.kinematics_surge_range", length, between(0.1, 200.0), 6.0,
              "Precomputed kinematics: the hull's surge from x = 0 the record covers (±); outside it a hull load takes "
              "the exact sums (counted in the run's record)."),
    defaulted("wave.kinematics_heave_range", length, between(0.1, 50.0), 2.0,
              "Precomputed kinematics: the hull's heave from its floating height the record covers (±)."),
    defaulted("wave.kinematics_pitch_range", angle, between(0.001, 0.5), 3.0 * kPi / 180.0,
              "Precomputed kinematics: the hull's pitch the record covers (±), with its unit: \"3 deg\".", "deg"),
    number_list("wave.component_frequencies", angular_velocity, above(0.0, 100.0),
                "components: angular frequencies ω_n (an array, numbers in rad/s)."),
    number_list("wave.component_amplitudes", length, between(0.0, 15.0),
                "components: amplitudes a_n (an array, numbers in m), each below the breaking limit a k < π/7."),
    number_list("wave.component_phases", angle, between(-100.0, 100.0),
                "components: phases φ_n of η(0, t) = Σ a_n cos(ω_n t + φ_n) (an array, numbers in rad)."),
    // [radiation]
    defaulted("radiation.surge_added_mass", ratio, between(0.0, 10.0), 0.0, "A11 as a multiple of the displaced mass."),
    defaulted("radiation.heave_added_mass", ratio, between(0.0, 10.0), 0.0, "A33 as a multiple of the displaced mass."),
    defaulted("radiation.pitch_added_inertia", ratio, between(0.0, 10.0), 0.0,
              "A55 as a multiple of the hull's pitch inertia I55 about G1."),
    defaulted("radiation.surge_damping", ratio, between(0.0, 2.0), 0.0, "B11 as a fraction of critical damping in surge."),
    defaulted("radiation.heave_damping", ratio, between(0.0, 2.0), 0.0, "B33 as a fraction of critical damping in heave."),
    defaulted("radiation.pitch_damping", ratio, between(0.0, 2.0), 0.0, "B55 as a fraction of critical damping in pitch."),
    // [bem]
    text("bem.radiation_file",
         "WAMIT .1 file (added mass and damping with the zero- and infinite-frequency rows), relative to the scene "
         "file. [bem] needs this or bem.capytaine_file."),
    text("bem.capytaine_file",
         "Capytaine NetCDF dataset (.nc, relative to the scene file) in place of the WAMIT files: added mass, "
         "radiation damping, Froude–Krylov and diffraction forces of the dofs Surge, Heave, Pitch, dimensional SI "
         "at the file's ρ (scaled to environment.water_density) and g (must equal environment.gravity). Excludes "
         "bem.radiation_file, excitation_file, hydrostatics_file and length_scale. docs/hydrodynamics.md §4.5."),
    choice("bem.infinite_frequency_added_mass", "kramers-kronig|high-frequency", "kramers-kronig",
           "A∞ of a Capytaine dataset without ω = ∞ (a warning names the method and both estimates): "
           "kramers-kronig = A(ω) − (2/π)PV∫B(ν)/(ν² − ω²)dν (median over the tabulated ω); high-frequency = "
           "A∞ + c/ω² fitted to the last 5 frequencies. Only for bem.capytaine_file."),
    text("bem.excitation_file", "WAMIT .3 file (excitation per unit amplitude); needed by bem.excitation = \"bem\"."),
    text("bem.hydrostatics_file", "WAMIT .hst file; checked against the box hull's waterplane (C33 = ρgLB within 2 %)."),
    defaulted("bem.length_scale", length, between(0.01, 1000.0), 1.0, "WAMIT's ULEN of the run that wrote the files."),
    defaulted("bem.origin_above_keel", length, between(-100.0, 200.0), 0.0,
              "Height of the BEM body origin above the keel (WAMIT's origin is usually on the free surface: the "
              "draft)."),
    defaulted("bem.origin_forward_of_mid_length", length, between(-500.0, 500.0), 0.0,
              "Distance of the BEM body origin forward of the hull's mid-length."),
    choice("bem.radiation_model", "constant|state-space|convolution", "convolution",
           "constant: A(ω_c), B(ω_c) (cheapest); convolution: Cummins with A∞ and the retardation function K(t) "
           "(the reference); state-space: a fitted realization of K(t). `--radiation` overrides it."),
    choice("bem.excitation", "froude-krylov|bem", "froude-krylov",
           "Incident-wave force: froude-krylov = the wave pressure on the wetted box; bem = Froude–Krylov + "
           "diffraction from bem.excitation_file (the pressure is then calm water: hydrostatics only)."),
    optional("bem.constant_period", time, between(0.5, 200.0),
             "Period at which the constant model takes A and B. Default: the wave's period."),
    defaulted("bem.state_space_tolerance", ratio, between(1e-4, 0.5), 0.02,
              "Impulse-response error e_r that fixes the state-space fit's order (smallest stable order within it)."),
    defaulted("bem.kernel_time_step", time, between(0.005, 0.5), 0.05, "Sampling step of the retardation function K(t)."),
    defaulted("bem.truncation_time", time, between(0.0, 600.0), 0.0,
              "Truncation time T_c of K(t) (0: automatic, where every entry stays below 10⁻³ of the peak)."),
    // [hull_damping]
    defaulted("hull_damping.surge_linear", linear_damping, between(0.0, 1e10), 0.0, "Linear surge damping b11: F = −b11 ẋ."),
    defaulted("hull_damping.heave_linear", linear_damping, between(0.0, 1e10), 0.0, "Linear heave damping b33: F = −b33 ẏ."),
    defaulted("hull_damping.pitch_linear", rotational_damping, between(0.0, 1e14), 0.0,
              "Linear pitch damping b55: M = −b55 θ̇."),
    defaulted("hull_damping.surge_quadratic", quadratic_damping, between(0.0, 1e10), 0.0,
              "Quadratic surge damping: F = −b ẋ |ẋ| (drag, ½ρ C_D A)."),
    defaulted("hull_damping.heave_quadratic", quadratic_damping, between(0.0, 1e10), 0.0,
              "Quadratic heave damping: F = −b ẏ |ẏ|."),
    defaulted("hull_damping.pitch_quadratic", rotational_quadratic_damping, between(0.0, 1e16), 0.0,
              "Quadratic pitch damping: M = −b θ̇ |θ̇|."),
    // [mooring]
    defaulted("mooring.surge_stiffness", stiffness, between(0.0, 1e10), 0.0,
              "Surge spring on the hull at G1. A floating hull needs it: nothing else restores surge, so its static "
              "equilibrium would be undetermined."),
    // [simulation]
    defaulted("simulation.duration", time, above(0.0, 1e6), 120.0,
              "Simulated time span; at most 1000000 output intervals."),
    defaulted("simulation.output_interval", time, between(1e-5, 3600.0), 0.05,
              "Interval between output samples; at most the duration."),
    choice("simulation.initial_state", "static-equilibrium|as-built", "static-equilibrium",
           "static-equilibrium: start from the static equilibrium (KINSOL); as-built: start from the "
           "undeformed posture as given."),
    defaulted("simulation.cargo_lift", length, between(0.0, 100.0), 0.0,
              "Raise the cargo this far above its starting posture and release it at rest: a dropped load whose "
              "wire goes slack and snaps taut (0: no lift)."),
    defaulted("simulation.deflection_limit", ratio, above(0.0, 2.0), 0.2,
              "Divergence detector: a run stops as diverged when the boom tip's elastic deflection exceeds this "
              "fraction of the boom length (the linear floating-frame model is meaningless beyond it)."),
    defaulted("simulation.constraint_drift_limit", length, between(1e-12, 100.0), 1e-3,
              "Constraint-drift detector: a full-coordinate run is flagged when the clamp residual |C| at B exceeds "
              "this."),
};

}  // namespace ffrf::scene::schema_table
