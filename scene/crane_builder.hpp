// Turns a loaded crane scene (scene/scene.hpp) into the coupled system of coupling/: the boom's
// nodal-space beam model, its elastic coordinates (rigid, nodal or modal), the hull's box section
// relative to G1, added mass and radiation damping from the scene's multiples and fractions of
// critical, the wire's damping, the wave. Documented modelling choices: docs/theory.md §7.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "modal/mode_cache.hpp"
#include "scene/scene.hpp"
#include "multibody/crane_parameters.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/stress_recovery.hpp"
#include "fem/axial_force.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/modal_coordinates.hpp"
#include "nodal/nodal_coordinates.hpp"

namespace ffrf::scene {

using multibody::StressRecovery;

enum class BoomKind { rigid, nodal, modal };
std::string_view to_string(BoomKind kind);
std::optional<BoomKind> parse_boom_kind(std::string_view text);
std::string boom_kind_choices();  // "rigid|nodal|modal"

struct BoomChoice {
  BoomKind kind = BoomKind::nodal;
  int elements = 16;          // N (the mesh the modes are computed on, for modal)
  int modes = 4;              // k vibration modes (modal)
  bool static_modes = false;  // add static correction modes (modal): tip loads + uniform body loads
  modal::EigenSolverKind solver = modal::EigenSolverKind::arpack;
  std::optional<Stiffening> stiffening = std::nullopt;  // overrides the scene's boom.stiffening
  // The modal boom's mode set: the reference condition of its floating frame and of its modes —
  // clamped-free (the frame clamped at the heel: the boom's root tangent), free-free (the unsupported
  // boom's modes less their root's rigid motion, in the same tangent frame) or, for a pinned heel,
  // pinned-pinned (the chord frame: the tip on the frame's axis). docs/theory.md, "Mode sets".
  fem::Boundary mode_set = fem::Boundary::clamped_free;
  // How the stresses along the boom are recovered from the elastic coordinates (a modal boom's
  // choice: mode displacement or mode acceleration; a nodal boom's are its own displacements', a
  // rigid boom's the quasi-static ones by mode acceleration). multibody/boom_stress.hpp.
  StressRecovery stress_recovery = StressRecovery::mode_acceleration;
  // "rigid", "nodal N=16", "modal k=4+static (N=16)", "modal k=2 pinned-pinned (N=16)",
  // "modal k=2 (N=16) (MD stress)"
  std::string label() const;
};

// The beam of the boom with its floating frame's reference condition (clamped at its root, or
// pinned at the root with the tip on the frame's axis).
std::shared_ptr<const fem::BeamModel> boom_beam(const Scene& scene, int elements,
                                                fem::Boundary reference = fem::Boundary::clamped_free);

// The boom's structural damping −(αM_ff + βK)η̇ from boom.damping_ratio ζ at the analytic bending
// frequencies ω1, ω2 of the boom as supported (clamped-free; pinned-pinned for a pinned heel, its tip
// held by the luffing wires): stiffness-proportional α = 0, β = 2ζ/ω1; rayleigh α = 2ζω1ω2/(ω1 + ω2),
// β = 2ζ/(ω1 + ω2). The same for every mesh and coordinate choice, so models compare on equal terms.
struct BoomDamping {
  double mass = 0.0;       // α [1/s]
  double stiffness = 0.0;  // β [s]
};
BoomDamping boom_damping(const Scene& scene);
inline double boom_stiffness_damping(const Scene& scene) { return boom_damping(scene).stiffness; }

// Boom angle above the horizontal in the as-built posture (hull crane: boom.angle; hub: hub.angle).
double boom_angle_at_rest(const Scene& scene);
// Signed distance along the boom axis from the axis the base turns about (hub axis, or G1 of a
// hull) to the root B: the r of the centrifugal axial force (negative when the axis lies ahead).
double centrifugal_hub_radius(const Scene& scene);
// The reference axial force of static stiffening: beam statics of the undeformed boom in its
// as-built posture under self-weight and the hanging cargo's weight at the tip (compression < 0):
// N(x) = −(ρA g (L − x) + m_c g) sin φ.
fem::AxialForce static_reference_axial_force(const Scene& scene);

// Throws SceneError when the scene has no base (hull or hub) or the hull cannot float the load.
// A hub scene becomes a held or driven base (multibody::PrescribedMotion) without water; a scene
// without [cargo] has no cargo coordinates. `stiffening` adds the geometric stiffness matrices.
template <fem::ElasticCoordinates Coords>
multibody::CraneParameters<Coords> build_crane_parameters(const Scene& scene, Coords coords, Stiffening stiffening = Stiffening::none,
                                                          StressRecovery stress_recovery = StressRecovery::mode_acceleration);

// Elastic coordinates for a choice (the rigid boom is modal coordinates with an empty basis).
// The vibration modes come from the cache (computed once per mesh) or, without one, from a
// cache of this call alone: the same solve either way (modal/mode_cache.hpp).
modal::ModalCoordinates modal_coordinates(const Scene& scene, const BoomChoice& choice, modal::ModeCache* cache = nullptr);

// The immutable model of a choice (multibody/crane_model.hpp), shared by the runs (and threads)
// that use it: scene/crane_model_cache.hpp builds each once.
std::shared_ptr<const multibody::CraneModel> build_crane_model(const Scene& scene, const BoomChoice& choice,
                                                                     modal::ModeCache* cache = nullptr);

// The hull (or hub) of a scene with its hydrodynamics, and the wave: what a crane model takes from
// the scene's waters (build_crane_parameters). Throws SceneError (a hull that cannot float the load).
struct SceneWaters {
  multibody::HullModel hull;
  std::optional<sea::WaveField> wave;  // empty: calm water (or a hub)
};
SceneWaters scene_waters(const Scene& scene);

// `model` (built from a scene that differs from `scene` at most in its waters: wave, sea, [bem]
// radiation model) with the waters of `scene`: equal to build_crane_model(scene, its choice)
// without rebuilding the boom (multibody::CraneModel::in_waters).
std::shared_ptr<const multibody::CraneModel> with_waters(const multibody::CraneModel& model, const Scene& scene);

// The whole system for a choice, ready for static equilibrium and integration: build_crane_model's
// model with its own workspace.
std::unique_ptr<multibody::CraneEquations> build_crane_equations(const Scene& scene, const BoomChoice& choice, modal::ModeCache* cache = nullptr);

}  // namespace ffrf::scene
