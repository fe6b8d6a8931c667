// A loaded scene (DESIGN.md §3): pure data in SI units, planar, y up, angles counter-clockwise.
// The boom is always present; a crane scene also has the hull, the cargo and the wire. Sections a
// scene leaves out take the defaults of cases/scene_schema.cpp (environment, radiation, mooring,
// simulation) or stay empty (wave: calm water).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::cases {

// Where and how the boom is clamped to the hull (crane scenes only).
struct BoomMount {
  double angle;   // above the hull's x axis [rad], in (0, π/2)
  double root_x;  // B relative to G1, hull frame [m]
  double root_y;  // [m]
};

struct Boom {
  fem::BeamMesh mesh;                 // length, element count N and section (E, A, I, ρA)
  fem::Boundary boundary;             // for `ffrf modes`; the crane clamps the root
  double damping_ratio;               // structural, fraction of critical in the first mode [-]
  std::optional<double> density;     // ρ [kg/m^3] when the scene gave it instead of ρA
  std::optional<BoomMount> mount;
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

enum class WaveDirection { following, head };  // following: travels +x

struct Wave {
  double height;        // H, trough to crest [m]
  double period;        // T [s]
  WaveDirection direction;
  double ramp_periods;  // ramp-in length in periods [-]
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

struct Mooring {
  double surge_stiffness;  // [N/m]
};

enum class InitialState { static_equilibrium, as_built };

struct Simulation {
  double duration;         // [s]
  double output_interval;  // [s]
  InitialState initial_state;
};

struct Scene {
  std::string file;  // path the scene was loaded from (for messages)
  std::string name;
  std::string description;
  Boom boom;
  std::optional<Hull> hull;
  std::optional<Cargo> cargo;
  std::optional<Wire> wire;
  Environment environment;
  std::optional<Wave> wave;  // empty: calm water
  Radiation radiation;
  Mooring mooring;
  Simulation simulation;

  bool is_crane() const { return hull.has_value(); }  // then cargo, wire and boom.mount are present
};

}  // namespace ffrf::cases
