// The crane's equations as the solvers see them (solve/second_order_system.hpp), and what the crane
// adds for its own recorders, detectors and studies: the outputs of a state, the wires' stretches,
// the layout of its coordinates (multibody/crane_layout.hpp) and the hull loads' counters.
//  * Minimal coordinates z = (hull x, y, θ | free bodies' x, y, θ | pinned bodies' γ | heel β | η)
//    (multibody/crane_layout.hpp): the boom frame is eliminated by the heel joint at B (a clamp leaves
//    no coordinate, a pin the luffing angle β), a body pinned to the hull by its pin (its angle γ
//    relative to the hull). Without hull DOFs when the hull is held fixed.
//  * Full coordinates q = (hull | every rigid body | boom R_B, θ_B, η) with the heel as 3 (clamp) or 2
//    (pin) constraints and each pinned body's pin as 2, C(q, t) = 0, and Lagrange multipliers:
//    M(q) q̈ = Q(q, q̇, t) − C_qᵀ λ (paper eqs. 17, 22, 31–34).
//    With a driven base (prescribed motion) C depends on t: C_q v + C_t = 0 at velocity level.
// The hull block is absent when the base is held or driven; the rigid bodies (the cargo, an A-frame)
// are the model's list, each with its block.
// The event functions are the wires' stretches ℓ − L0 (slack below zero), one per wire.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "multibody/crane_layout.hpp"
#include "multibody/wire_role.hpp"
#include "solve/second_order_system.hpp"

namespace ffrf::sea {
class IncidentWaveRecord;  // sea/incident_wave_record.hpp
}  // namespace ffrf::sea

namespace ffrf::multibody {

using solve::BandStructure;
using solve::BorderedBandMatrix;
using solve::ConstraintMatrix;
using solve::ConstraintVector;
using solve::MassMatrixError;
using solve::SecondOrderJacobian;

// One output sample: what a time-series row and the static report show.
struct CraneOutputs {
  Eigen::Vector3d hull = Eigen::Vector3d::Zero();        // G1 (or hub) x [m], y [m], pitch [rad]
  Eigen::Vector3d cargo = Eigen::Vector3d::Zero();       // G2 x [m], y [m], pitch [rad]
  Eigen::Vector2d tip_deflection = Eigen::Vector2d::Zero();  // elastic (u, v) at A′ in the boom frame [m]
  double wire_tension = 0.0;                             // the hoist wire's [N]
  double wire_length = 0.0;                              // [m]
  double luffing_tension = 0.0;                          // all luffing wires together [N] (a pinned boom's)
  double luffing_line_pull = 0.0;                        // the largest luffing rope tension: a wire's pull / its parts of line [N]
  double backstay_tension = 0.0;                         // all backstays together [N] (an A-frame pinned to the deck)
  double a_frame_rotation = 0.0;                         // the A-frame's angle γ about its pin relative to the hull [rad]
  Eigen::Vector3d joint_reaction = Eigen::Vector3d::Zero();  // on the boom at B: Fx, Fy [N] (global), M [N m]
  double root_axial_force = 0.0;                         // boom axial force at B, tension > 0 [N]
  double constraint_residual = 0.0;                      // |C(q)| (0 in minimal coordinates) [m]
  double kinetic_energy = 0.0;                           // [J] (added mass included)
  double gravity_energy = 0.0;                           // [J]
  double strain_energy = 0.0;                            // [J]
  double wire_energy = 0.0;                              // [J]
  double spring_energy = 0.0;                            // mooring + support springs [J]
  // Stresses along the boom (multibody/boom_stress.hpp; zero without a stress model): the largest
  // extreme-fibre stress over the sections by the model's recovery, where it sits, its ratio to the
  // allowable stress (0 without one), and the peak by each recovery (mode displacement, mode
  // acceleration; equal for nodal coordinates).
  double boom_peak_stress = 0.0;           // [Pa]
  double boom_peak_stress_position = 0.0;  // x along the boom from B [m]
  double boom_stress_utilisation = 0.0;    // [-]
  std::array<double, 2> boom_peak_stress_by{};  // [Pa], by StressRecovery
};

struct BoomStressProfile;  // multibody/boom_stress_profile.hpp

// How this system's hull loads read the incident wave so far: from the record of the sea, or by
// the exact component sums where the record could not answer (outside its patches or its time).
struct HullLoadCounts {
  long recorded = 0;
  long exact = 0;  // with a record: the fallbacks
};

class CraneEquations : public solve::SecondOrderSystem {
 public:
  // The outputs at a state: minimal coordinates (the joint reaction solved from the equations of
  // motion), full coordinates with the multipliers λ, or minimal coordinates with the accelerations
  // z̈ known (an integrator's interpolant: the reaction from them, without solving; by default
  // minimal_outputs(t, z, ż)). Sampling also records the hull's velocity for the radiation memory.
  virtual CraneOutputs minimal_outputs(double t, ConstRef z, ConstRef z_dot) = 0;
  virtual CraneOutputs full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) = 0;
  virtual CraneOutputs minimal_outputs_with_accelerations(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) {
    (void)z_ddot;
    return minimal_outputs(t, z, z_dot);
  }
  double minimal_kinetic_energy(double t, ConstRef z, ConstRef z_dot) override {
    return minimal_outputs(t, z, z_dot).kinetic_energy;
  }

  // The wires (multibody/crane_parameters.hpp: WireConnector): how many, which one carries the cargo
  // (−1: none), their names, and their stretches ℓ − L0 [m] (slack below zero), one per wire.
  virtual int wire_count() const = 0;
  virtual int hoist_wire() const = 0;
  virtual std::string wire_name(int wire) const = 0;
  virtual WireRole wire_role(int wire) const = 0;
  virtual void wire_stretches_minimal(double t, ConstRef z, Ref stretch) = 0;
  virtual void wire_stretches_full(double t, ConstRef q, Ref stretch) = 0;
  // The event functions: every wire's stretch, event i the wire i.
  int event_count() const override { return wire_count(); }
  void minimal_events(double t, ConstRef z, Ref g) override { wire_stretches_minimal(t, z, g); }
  void full_events(double t, ConstRef q, Ref g) override { wire_stretches_full(t, q, g); }

  // Where each body's and joint's coordinates sit (multibody/crane_layout.hpp), and the rigid bodies'
  // names in its order ("cargo", "A-frame").
  virtual const CraneLayout& layout() const = 0;
  virtual std::string body_name(int body) const = 0;
  // The cargo's place among the rigid bodies (−1: none), and the index of its (x, y, θ) in the minimal
  // coordinates (−1 without a cargo).
  virtual int cargo_body() const = 0;
  int cargo_offset() const { return cargo_body() < 0 ? -1 : layout().bodies[cargo_body()].minimal; }
  // Index of the pinned heel's luffing angle β in the minimal coordinates; −1 for a clamped boom.
  int heel_offset() const { return layout().heel; }
  // Elastic coordinate count (0 for the rigid boom).
  virtual int elastic_size() const = 0;
  // The stresses along the boom at the last output sample, by the model's recovery (nullptr when the
  // model recovers none).
  virtual const BoomStressProfile* boom_stress_profile() const { return nullptr; }
  // Hull-load evaluations in a wave so far, by path (zeros without a wave).
  virtual HullLoadCounts hull_load_counts() const { return {}; }
  // The record of the sea the hull loads read (nullptr: component sums), and why not when absent.
  virtual const sea::IncidentWaveRecord* wave_record() const { return nullptr; }
  virtual std::string exact_kinematics_reason() const { return {}; }

  // The static solver's view of the rows: hull (surge, heave, pitch) when it floats, each free body's
  // (x, y, θ), each pinned body's moment about its pin, the pinned heel's moment, then the boom's
  // elastic coordinates, each with what to check when it stays out of balance.
  solve::ResidualRow residual_row(int row) const override;
  std::string static_model_check() const override;
  std::vector<int> rigid_body_blocks() const override;
};

}  // namespace ffrf::multibody
