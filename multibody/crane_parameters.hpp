// The floating crane as constant data (the "model", Pinocchio style), as components: the bodies —
// hull G1 (rigid, floating or held; it carries the sea loads and the boom's heel), the elastic boom on a
// floating frame, and a list of further rigid bodies (multibody/rigid_body_model.hpp: the cargo G2, an
// A-frame pinned to the deck) — and the connectors between them — the boom's heel joint at B on the
// hull (clamp or pin), the pins of the pinned bodies, and the wires (tension-only ropes between two
// body points: the hoist wire from the boom tip A′ to the hook C, the luffing wires, the backstays) —
// and the environment. The index map of their coordinates is multibody/crane_layout.hpp. Built once
// from a scene (scene/crane_builder.hpp); read-only in a run: it becomes part of a CraneModel
// (multibody/crane_model.hpp) that threads share.
// Planar, SI units, y up, angles counter-clockwise (docs/architecture.md, "Conventions").
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sea/bem_excitation.hpp"
#include "multibody/floating_frame_body.hpp"
#include "sea/hull_pressure.hpp"
#include "multibody/prescribed_motion.hpp"
#include "multibody/rigid_body_model.hpp"
#include "multibody/wire_role.hpp"
#include "sea/wave_field.hpp"
#include "hydro/radiation_memory.hpp"

namespace ffrf::sea {
class IncidentWaveRecord;  // sea/incident_wave_record.hpp
class ExcitationRecord;    // sea/excitation_record.hpp
}  // namespace ffrf::sea

namespace ffrf::multibody {

struct BoomStressModel;  // multibody/boom_stress.hpp

struct HullModel {
  double mass = 0.0;                                        // without the boom [kg]
  double pitch_inertia = 0.0;                               // about G1 [kg m²]
  sea::BoxHullSection section{};                                 // box, hull frame at G1
  Eigen::Vector3d added_mass = Eigen::Vector3d::Zero();     // A11, A33, A55 (surge, heave, pitch)
  Eigen::Vector3d radiation_damping = Eigen::Vector3d::Zero();  // B11, B33, B55 [N s/m, N m s/rad]
  // Damping beside the radiation (viscous, skin friction), per DOF at G1: F_i = −b_i v_i − q_i |v_i| v_i;
  // kept whatever the radiation model ([radiation] or [bem]).
  Eigen::Vector3d added_linear_damping = Eigen::Vector3d::Zero();  // b [N s/m, N s/m, N m s/rad]
  Eigen::Vector3d quadratic_damping = Eigen::Vector3d::Zero();     // q [N s²/m², N s²/m², N m s²/rad²]
  // Radiation from BEM coefficients, referred to G1 (hydro/radiation_memory.hpp): constant A(ω_c),
  // B(ω_c), Cummins convolution or its state-space fit; its 3 × 3 added mass joins the hull's mass.
  // Empty: the diagonal added_mass and radiation_damping above.
  std::shared_ptr<const hydro::RadiationMemoryModel> radiation_memory;
  // First-order excitation from BEM (Froude–Krylov + diffraction) at G1; when set, the pressure is
  // integrated in calm water (hydrostatics only), so Froude–Krylov is counted once.
  std::shared_ptr<const sea::BemExcitation> bem_excitation;
  // The same excitation recorded once per record (sea/excitation_record.hpp); empty: summed.
  std::shared_ptr<const sea::ExcitationRecord> bem_excitation_record;
  // The incident sea of this record evaluated once (sea/incident_wave_record.hpp): the hull
  // pressure reads the wave from it, and takes the exact component sums wherever it cannot answer.
  // Empty: every evaluation sums the components (regular waves, exact kinematics, finite depth).
  std::shared_ptr<const sea::IncidentWaveRecord> wave_record;
  std::string exact_kinematics_reason;  // without a record in a wave: why (for reports)
  double mooring_stiffness = 0.0;                           // surge spring [N/m], anchored at x = 0
  bool hydrostatics = true;                                 // pressure integration on/off
  // Linear support springs towards `support_pose` (surge, heave, pitch): test scenes that hold the
  // hull without water. Zero = none.
  Eigen::Vector3d support_stiffness = Eigen::Vector3d::Zero();
  Eigen::Vector3d support_pose = Eigen::Vector3d::Zero();  // also the pose of a fixed hull
  bool fixed = false;  // hull held at its initial pose (its coordinates removed)
  // A driven base (hub): fixed = true and the pose follows this driving constraint instead of support_pose.
  std::optional<PrescribedMotion> prescribed;
};

// The boom's heel joint at B: a clamp (the frame turns with the hull: the source paper's model) or a
// pin (the frame's angle relative to the hull is a coordinate, the luffing angle β from `angle`).
enum class HeelJoint { clamp, pin };

struct BoomMountModel {
  Eigen::Vector2d root = Eigen::Vector2d::Zero();  // B relative to G1, hull frame [m]
  double angle = 0.0;                              // boom frame angle relative to the hull [rad] (at β = 0)
  HeelJoint joint = HeelJoint::clamp;
};


struct WireModel {
  double unstretched_length = 0.0;  // L0 [m]
  double stiffness = 0.0;           // [N/m]
  double damping = 0.0;             // [N s/m]
};

// The bodies a connector can attach to: the hull, the boom, or one of the rigid bodies of
// CraneParameters::bodies.
enum class Body { hull, boom, rigid };

// A point of a body: in the body's frame (the hull's at G1, a rigid body's at its G, the boom's
// floating frame at B with its shape rows).
struct BodyAttachment {
  Body body = Body::hull;
  int index = -1;  // Body::rigid: the body's place in CraneParameters::bodies
  BodyPoint point;
};

inline BodyAttachment on_hull(const Eigen::Vector2d& point) {
  BodyAttachment end{Body::hull, -1, {}};
  end.point.undeformed = point;
  return end;
}
inline BodyAttachment on_boom(BodyPoint point) { return {Body::boom, -1, std::move(point)}; }
inline BodyAttachment on_rigid_body(int index, const Eigen::Vector2d& point) {
  BodyAttachment end{Body::rigid, index, {}};
  end.point.undeformed = point;
  return end;
}



// A wire rope between two body points (multibody/wire_rope.hpp: tension only); its tension pulls the
// two ends towards each other. Reeved as a tackle of `parts` parts of line between two sheave blocks,
// `rope` is the tackle's (the pull between the blocks: n times one part's stiffness and stretch
// force), and each part of the rope carries the pull / n (the line pull).
struct WireConnector {
  std::string name;  // "hoist wire": for events and messages
  WireModel rope;
  BodyAttachment from, to;
  int parts = 1;  // parts of line (1: a single rope between the points)
  WireRole role = WireRole::hoist;
};

template <fem::ElasticCoordinates Coords>
struct CraneParameters {
  HullModel hull;
  BoomMountModel mount;
  FloatingFrameBody<Coords> boom;
  BodyPoint boom_tip;  // A′ (x = L): the tip deflection's point
  std::vector<RigidBodyModel> bodies{};  // the rigid bodies beside the hull: the cargo, an A-frame, ...
  int cargo = -1;                      // the cargo's place in `bodies` (−1: none): it hangs on the hoist wire
  int a_frame = -1;                    // the A-frame's place in `bodies` (−1: rigid with the hull)
  std::vector<WireConnector> wires{};  // every rope: the hoist wire first when there is a cargo
  int hoist_wire = -1;                 // the cargo's wire in `wires` (−1: none)
  double gravity = 9.81;
  double water_density = 1025.0;
  std::optional<sea::WaveField> wave;  // empty: calm water
  // How the stresses along the boom are recovered at each output (multibody/boom_stress.hpp); empty: none.
  std::shared_ptr<const BoomStressModel> stress{};
};

// The same crane without its cargo and hoist wire (a boom on its supports alone): the cargo's body
// and wire removed, the other bodies' indices in the wires' ends renumbered.
template <class Parameters>
void remove_cargo(Parameters& crane) {
  if (crane.hoist_wire >= 0) {
    crane.wires.erase(crane.wires.begin() + crane.hoist_wire);
    crane.hoist_wire = -1;
  }
  if (crane.cargo < 0) return;
  const int removed = crane.cargo;
  for (const WireConnector& wire : crane.wires) {
    for (const BodyAttachment* end : {&wire.from, &wire.to}) {
      if (end->body == Body::rigid && end->index == removed) {
        throw std::invalid_argument("remove_cargo: the " + wire.name + " ends on the cargo besides its hoist wire");
      }
    }
  }
  crane.bodies.erase(crane.bodies.begin() + removed);
  for (WireConnector& wire : crane.wires) {
    for (BodyAttachment* end : {&wire.from, &wire.to}) {
      if (end->body == Body::rigid && end->index > removed) --end->index;
    }
  }
  if (crane.a_frame > removed) --crane.a_frame;
  crane.cargo = -1;
}

}  // namespace ffrf::multibody
