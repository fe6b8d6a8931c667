// A loaded scene (docs/scenes.md): pure data in SI units, planar, y up, angles counter-clockwise.
// The boom is always present; a crane scene also has the hull, the cargo and the wire. Sections a
// scene leaves out take the defaults of scene/scene_schema_table.hpp (environment, radiation, mooring,
// simulation) or stay empty (wave: calm water).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"
#include "hydro/wave_synthesis.hpp"
#include "hydro/added_mass_symmetry.hpp"
#include "hydro/infinite_frequency.hpp"
#include "hydro/planar_coefficients.hpp"
#include "hydro/radiation_memory.hpp"

namespace ffrf::scene {

// Where and how the boom is clamped to the hull (crane scenes only).
struct BoomMount {
  double angle;   // above the hull's x axis [rad], in (0, π/2); a pinned boom's nominal angle
  double root_x;  // B relative to G1, hull frame [m]
  double root_y;  // [m]
  bool pinned = false;  // the heel is a revolute joint held by the [luffing] wires
};

// The luffing wires of a pinned boom ([luffing]): from the A-frame top on the hull to a boom point.
struct Luffing {
  double a_frame_x, a_frame_y;  // A-frame top relative to G1, hull frame [m]
  double stiffness;             // each wire's, of one part of line when reeved [N/m]
  int wires = 1;                // parallel wires
  std::optional<double> attachment;          // from the heel along the boom [m] (empty: the tip)
  std::optional<double> unstretched_length;  // each wire [m] (empty: holds the rigid boom at boom.angle)
  double damping_ratio = 0.0;
  int parts = 1;  // parts of line in each wire's tackle: the tackle is `parts` times as stiff as one part
};

// The A-frame as a rigid body pinned to the deck ([a_frame]), its top the luffing wires' far end
// (luffing.a_frame_x, luffing.a_frame_y), and the backstays that hold it ([backstay]).
struct AFrame {
  double pin_x, pin_y;                        // its foot pin relative to G1, hull frame [m]
  double mass;                                // [kg]
  std::optional<double> radius_of_gyration;  // about its centre of mass [m] (empty: |top − pin|/√12)
};
struct Backstay {
  double deck_x, deck_y;  // the deck point relative to G1, hull frame [m]
  double stiffness;       // each wire's [N/m]
  int wires = 1;
  std::optional<double> unstretched_length;  // each wire [m] (empty: holds the A-frame at rest)
  double damping_ratio = 0.0;
};

// Geometric (stress) stiffening of the boom (docs/theory.md, "Geometric stiffening").
enum class Stiffening { none, static_load, centrifugal, both };
std::string_view to_string(Stiffening stiffening);                  // "none", "static", "centrifugal", "both"
std::optional<Stiffening> parse_stiffening(std::string_view text);  // nullopt when unknown
inline bool has_static_stiffening(Stiffening s) { return s == Stiffening::static_load || s == Stiffening::both; }
inline bool has_centrifugal_stiffening(Stiffening s) { return s == Stiffening::centrifugal || s == Stiffening::both; }

struct Boom {
  fem::BeamMesh mesh;                 // length, element count N and section (E, A, I, ρA)
  fem::Boundary boundary;             // for `ffrf modes`; the crane clamps the root
  double damping_ratio;               // structural, fraction of critical in the first mode [-]
  bool rayleigh_damping = false;      // ζ in the first two modes (mass + stiffness), not the first alone
  std::optional<double> density;     // ρ [kg/m^3] when the scene gave it instead of ρA
  std::optional<BoomMount> mount;     // hull cranes: as given; hub scenes: (0, hub.radius, 0)
  Stiffening stiffening = Stiffening::none;
  double fibre_distance = 0.0;            // c of the extreme fibres [m] (given, or sqrt(I/A))
  std::optional<double> allowable_stress;  // of the extreme fibre [Pa]
};

struct Hull {
  double mass;                       // without the boom [kg]
  double pitch_radius_of_gyration;   // about G1 [m]
  double length;                     // box, x [m]
  double width;                      // box, normal to the plane [m]
  double depth;                      // box, keel to deck [m]
  double g1_above_keel;              // [m]
  double g1_aft_of_mid_length;       // [m], < 0: forward of mid-length

  double pitch_inertia() const { return mass * pitch_radius_of_gyration * pitch_radius_of_gyration; }  // [kg m^2]
};

// A rigid hub on a fixed axis with a prescribed rotation (the base of a hub scene instead of a hull).
enum class HubMotion { fixed, spin_up, constant_spin };

struct Hub {
  double radius;        // axis to boom root [m]
  double angle;         // θ(0) [rad]
  HubMotion motion;
  double spin_rate;     // Ωs [rad/s]
  double spin_up_time;  // Ts [s]
};

struct Cargo {
  double mass;                      // [kg]
  double length;                    // box, x [m]
  double height;                    // box, y [m]
  double hook_x;                    // C relative to G2, cargo frame [m]
  double hook_y;                    // [m]
  double pitch_radius_of_gyration;  // about G2 [m] (given, or the uniform box's)
  bool radius_of_gyration_derived;  // true when computed from the box

  double pitch_inertia() const { return mass * pitch_radius_of_gyration * pitch_radius_of_gyration; }  // [kg m^2]
};

struct Wire {
  double unstretched_length;  // L0 [m]
  double stiffness;           // EA/L0 [N/m]
  double damping_ratio;       // fraction of critical [-]
};

struct Environment {
  double water_density;  // ρ [kg/m^3]
  double gravity;        // g [m/s^2]
  double water_depth;    // [m], infinity = deep water

  bool deep_water() const { return std::isinf(water_depth); }
};


struct Wave {
  double height;        // H, trough to crest [m]
  double period;        // T [s]
  hydro::WaveHeading direction;  // following: travels +x
  double ramp_periods;  // ramp-in length in periods [-]
};

// An irregular long-crested sea ([wave] with spectrum ≠ regular; docs/hydrodynamics.md §2.2): a
// parametric spectrum synthesized with random phases (scene/irregular_sea.hpp), or user components
// η(0, t) = Σ a_n cos(ω_n t + φ_n). Exclusive with Scene::wave (the regular wave).
enum class SeaSpectrum { jonswap, pierson_moskowitz, components };

// How a hull load reads the incident sea: recorded once per record, or summed component by component.
enum class WaveKinematics { precomputed, exact };

// The motion range a recorded sea covers around the floating hull (± surge, heave [m], pitch [rad]).
struct KinematicsRange {
  double surge = 6.0, heave = 2.0, pitch = 0.05235987755982988;  // pitch 3°
};

struct IrregularSea {
  SeaSpectrum spectrum = SeaSpectrum::jonswap;
  double significant_height = 0.0;  // Hs [m] (jonswap, pierson-moskowitz)
  double peak_period = 0.0;         // Tp [s]
  double peak_enhancement = 3.3;    // γ [-] (jonswap)
  double sigma_below = 0.07;        // σa, ω ≤ ωp (jonswap)
  double sigma_above = 0.09;        // σb, ω > ωp (jonswap)
  hydro::WaveHeading heading = hydro::WaveHeading::following;
  std::uint64_t seed = 1;
  int component_count = 0;          // 0: Δω = 2π / simulation.duration over the band
  double frequency_min = 0.0;       // band [rad/s]; both 0: the band holding all but 0.1 % of m0
  double frequency_max = 0.0;
  bool random_amplitudes = false;   // Rayleigh-distributed amplitudes
  std::vector<double> component_frequencies;  // ω_n [rad/s] (components)
  std::vector<double> component_amplitudes;   // a_n [m]
  std::vector<double> component_phases;       // φ_n [rad]
  double ramp_periods = 2.0;        // ramp-in over this many Tp (components: the longest period)
  WaveKinematics kinematics = WaveKinematics::precomputed;
  double kinematics_tolerance = 1e-5;  // [m] of the recorded incident wave
  KinematicsRange kinematics_range;
};

// Constant radiation coefficients (hull frame at G1) as multiples / fractions of critical.
struct Radiation {
  double surge_added_mass;     // A11 / displaced mass [-]
  double heave_added_mass;     // A33 / displaced mass [-]
  double pitch_added_inertia;  // A55 / I55 [-]
  double surge_damping;        // B11, fraction of critical [-]
  double heave_damping;        // B33 [-]
  double pitch_damping;        // B55 [-]
};

// Hull hydrodynamics from WAMIT files or a Capytaine dataset ([bem]; docs/hydrodynamics.md §6): the
// files as read (at the BEM body origin, ffrf's signs), where that origin lies on the hull, and
// which models use them.
enum class ExcitationModel { froude_krylov, bem };  // who owns the incident-wave force (§6 table)
enum class BemFormat { wamit, capytaine };          // .1/.3/.hst, or one NetCDF dataset (bem.capytaine_file)

struct BemHull {
  BemFormat format = BemFormat::wamit;
  std::string radiation_file;                 // .1 or the .nc, resolved against the scene file's folder
  std::string excitation_file;                // .3 or the .nc ("" = none)
  std::string hydrostatics_file;              // .hst ("" = none)
  double length_scale = 1.0;                  // ULEN [m]
  double origin_above_keel = 0.0;             // BEM origin, hull frame [m]
  double origin_forward_of_mid_length = 0.0;  // [m]
  hydro::RadiationKind radiation_model = hydro::RadiationKind::convolution;
  ExcitationModel excitation = ExcitationModel::froude_krylov;
  std::optional<double> constant_period;      // [s] A, B of the constant model (default: the wave's period)
  double state_space_tolerance = 0.02;        // impulse-response error e_r of the fit [-]
  double kernel_time_step = 0.05;             // K(t) sampling [s]
  double truncation_time = 0.0;               // T_c [s], 0 = automatic
  hydro::InfiniteFrequencyMethod infinite_frequency_method = hydro::InfiniteFrequencyMethod::kramers_kronig;
  hydro::PlanarRadiation radiation;           // A(ω), B(ω), A(0), A∞ (every A symmetric: see below)
  std::optional<hydro::InfiniteFrequencyEstimate> infinite_frequency_estimate;  // A∞ not in the file: estimated
  // What making the added mass symmetric removed when the files were read (hydro/added_mass_symmetry.hpp).
  hydro::AddedMassAsymmetry added_mass_asymmetry;
  std::optional<hydro::PlanarExcitation> excitation_table;
  std::optional<hydro::PlanarMatrix> hydrostatics;  // C
};

// Damping added to the hull at G1 ([hull_damping]): F_i = −b_i v_i − q_i |v_i| v_i per DOF
// (surge, heave, pitch), beside the radiation of [radiation] or [bem].
struct HullDamping {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();     // [N s/m, N s/m, N m s/rad]
  Eigen::Vector3d quadratic = Eigen::Vector3d::Zero();  // [N s²/m², N s²/m², N m s²/rad²]
};

struct Mooring {
  double surge_stiffness;  // [N/m]
};

enum class InitialState { static_equilibrium, as_built };

struct Simulation {
  double duration;         // [s]
  double output_interval;  // [s]
  InitialState initial_state;
  double cargo_lift = 0.0;              // [m] raise the cargo and release it at rest
  double deflection_limit = 0.2;        // divergence: tip deflection / boom length [-]
  double constraint_drift_limit = 1e-3; // [m]
};

struct Scene {
  std::string file;  // path the scene was loaded from (for messages)
  // Values given beside the file ("boom.angle=55 deg": `--set`, Python's `with_values`), in the order
  // given; the loader checked them with the file's (scene/scene_overrides.hpp).
  std::vector<std::string> overrides;
  std::string name;
  std::string description;
  Boom boom;
  std::optional<Hull> hull;
  std::optional<Hub> hub;    // excludes hull
  std::optional<Cargo> cargo;
  std::optional<Wire> wire;
  std::optional<Luffing> luffing;  // with a pinned heel
  std::optional<AFrame> a_frame;    // with [luffing]: the A-frame pinned to the deck (empty: rigid with the hull)
  std::optional<Backstay> backstay;  // with [a_frame]
  Environment environment;
  std::optional<Wave> wave;  // the regular wave; empty: calm water or an irregular sea
  std::optional<IrregularSea> sea;  // an irregular sea (excludes wave)
  Radiation radiation;
  std::optional<BemHull> bem;  // hull coefficients from BEM files (replaces [radiation])
  HullDamping hull_damping;
  Mooring mooring;
  Simulation simulation;
  // What the loader's physics checks found doubtful but not wrong (scene/scene_checks.hpp), each
  // as "FILE:LINE: key = value: message"; the commands print them before any work.
  std::vector<std::string> warnings;

  bool is_crane() const { return hull.has_value(); }  // then cargo, wire and boom.mount are present
  bool has_base() const { return hull.has_value() || hub.has_value(); }  // a time-domain system: hull or hub
  bool has_cargo() const { return cargo.has_value(); }  // then wire too
};

}  // namespace ffrf::scene
