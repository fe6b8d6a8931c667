// Stresses along the elastic boom at an output sample: the section forces (axial force N, bending
// moment M) and the extreme-fibre stresses N/A ∓ M c/I at every node of a nodal mesh
// (fem/section_forces.hpp), recovered from the boom's motion in one of two ways (docs/theory.md §13):
//  * mode displacement: the nodal displacements the elastic coordinates stand for, q_n = Φ η
//    (for nodal coordinates Φ = I: the finite-element answer itself);
//  * mode acceleration: q_n = Φ η + (K + K_σ)⁻¹ r, with r the residual of the nodal finite-element
//    equations of the floating-frame body at the modal motion,
//        r = Q_f(q_n, q̇_n) + Σ S(x_p)ᵀ Aᵀ F_p − M_fR q̈_B − M_ff Φ η̈,
//    Q_f the body's own elastic-row loads (gravity, quadratic velocity, −(K + K_σ) q_n, damping),
//    F_p the wires' pulls at their boom points and q̈_B the frame's acceleration — the static response
//    of the nodal model to every load the truncated basis leaves unbalanced (Φᵀ r = 0 by the modal
//    equations). For nodal coordinates r = 0 and both ways agree; a rigid boom (Φ empty) has no
//    mode-displacement stress, and its mode-acceleration stress is the quasi-static one.
// Either way the section forces are each element's end forces r_e = K_e(q_e + βq̇_e) + K_σ,e q_e +
// θ̇² K_c,e q_e − f_e, f_e the element's consistent loads of what is distributed along it in the
// floating frame (its weight and inertia: frame translation and rotation, centrifugal, Coriolis and
// relative acceleration, the mass-proportional damping) and of a wire's pull inside it — exact at the
// nodes for exact nodal displacements.
// The model (what to recover, on which mesh) is constant data of the crane; the workspace and the
// profile belong to the evaluating equations (one per thread).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fem/axial_force.hpp"
#include "fem/beam_model.hpp"
#include "fem/section_forces.hpp"
#include "fem/shape_integrals.hpp"
#include "multibody/boom_stress_profile.hpp"
#include "multibody/floating_frame_body.hpp"
#include "multibody/stress_recovery.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace ffrf::multibody {

// A force on the boom at a sample: a wire's pull at its boom point.
struct BoomPointLoad {
  double x = 0.0;                                    // along the boom [m]
  Eigen::Vector2d force = Eigen::Vector2d::Zero();   // global frame [N]
};

// A point of the nodal body where a wire acts, its shape rows made once (mode acceleration's nodal load).
struct BoomLoadPoint {
  double x = 0.0;  // along the boom [m]
  BodyPoint point;
};

using ElementMatrix = Eigen::Matrix<double, 6, 6>;

// What the recovery needs to know, from the scene's builder.
struct BoomStressInputs {
  std::shared_ptr<const fem::BeamModel> beam;  // the nodal mesh the stresses are recovered on
  Eigen::MatrixXd basis;                       // Φ: free DOFs × elastic coordinates (unused when identity_basis)
  bool identity_basis = false;                 // nodal coordinates (Φ = I)
  double fibre_distance = 0.0;                 // c [m]
  double allowable_stress = 0.0;               // [Pa]; 0: none given
  StressRecovery method = StressRecovery::mode_displacement;  // the one the output channels report
  double stiffness_damping = 0.0, mass_damping = 0.0;         // β [s], α [1/s] of the boom's damping
  fem::AxialForce prestress, centrifugal;  // reference axial forces of the geometric stiffening (empty: none)
  std::vector<double> load_points;         // where the wires act on the boom [m] (their nodal points made once)
  bool mode_acceleration = false;          // build the nodal body and K + K_σ's factor (modal and rigid booms)
};

struct BoomStressModel {
  std::shared_ptr<const fem::BeamModel> beam;
  Eigen::MatrixXd basis;
  bool identity_basis = false;
  double fibre_distance = 0.0;
  double allowable_stress = 0.0;
  StressRecovery method = StressRecovery::mode_displacement;
  double stiffness_damping = 0.0, mass_damping = 0.0;
  // Per element: its invariants, its stiffness and geometric stiffnesses (empty vectors: no stiffening).
  std::vector<fem::ElementInvariants> elements;
  ElementMatrix element_stiffness = ElementMatrix::Zero();
  std::vector<ElementMatrix> prestress_elements, centrifugal_elements;
  std::vector<BoomLoadPoint> load_points;
  // Mode acceleration: the nodal floating-frame body on `beam` with the boom's damping and geometric
  // stiffening, and the factor of its static stiffness K + K_σ.
  std::shared_ptr<const FloatingFrameBody<nodal::NodalCoordinates>> nodal_body;
  std::shared_ptr<const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> static_stiffness;

  bool has_mode_acceleration() const { return nodal_body != nullptr; }
  int section_count() const { return beam->mesh.node_count(); }
};

// Throws std::invalid_argument for a non-positive fibre distance, a basis that does not fit the mesh,
// mode acceleration without its data, or K + K_σ not positive definite (a prestress beyond buckling).
BoomStressModel make_boom_stress_model(BoomStressInputs inputs);

// The boom's motion at a sample: its frame (R_B, θ_B) with velocity and acceleration, and its
// elastic coordinates with their rates and accelerations.
struct BoomMotion {
  Eigen::Vector3d frame_pose = Eigen::Vector3d::Zero(), frame_velocity = Eigen::Vector3d::Zero(),
                  frame_acceleration = Eigen::Vector3d::Zero();
  Eigen::VectorXd elastic, elastic_rate, elastic_acceleration;
};

struct BoomStressWorkspace {
  Eigen::VectorXd nodal_q, nodal_v, nodal_a, full_q, full_v, force, residual;
  Eigen::VectorXd full_displacement, full_velocity, full_acceleration, transverse_load;
  Eigen::Matrix3d reference = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, Eigen::Dynamic> coupling;
  std::vector<fem::ElementForces> end_forces;
  fem::SectionForces nodal_sections;  // N and M at the nodes (both elements' ends averaged)
  BodyWorkspace body;
};

// The profile by `method` (mode acceleration requires model.has_mode_acceleration()) under the point
// loads on the boom (the wires' pulls at their boom points).
void recover_boom_stress(const BoomStressModel& model, StressRecovery method, const BoomMotion& motion,
                         std::span<const BoomPointLoad> loads, const Eigen::Vector2d& gravity, BoomStressProfile& out,
                         BoomStressWorkspace& work);

}  // namespace ffrf::multibody
