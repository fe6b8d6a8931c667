// The natural modes of a pinned boom as the crane supports it: pinned at its heel on a held deck
// (the hull at its as-built pose, no water), held by its luffing wires (elastic, tension only,
// pretensioned by the boom's weight), under its own weight, without the cargo and its hoist wire.
// The nodal boom on N elements with the scene's geometric stiffening; the crane equations solved
// for that static equilibrium and linearised about it (multibody/linearisation.hpp), then
// K φ = ω² M φ in the minimal coordinates (the heel's luffing angle β and the boom's elastic
// coordinates) by Eigen's generalized self-adjoint solver. A mode whose potential energy the boom's
// own deformation stores less than half of (the wires and gravity the rest) is the boom's swing
// about its heel on the wires' spring; of the others, those with over half their kinetic energy in
// the axial motion are axial, the rest bending — unless the crane's A-frame stands on its own pin
// (held by its backstays) and its rocking has over half the mode's kinetic energy: an A-frame mode;
// beside each bending
// mode, the simply supported span's (pinned–pinned) Euler–Bernoulli frequency
// f_n = (nπ)² √(EI / ρA L⁴) / 2π, which the supported boom approaches as its wires stiffen.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace ffrf::study {

struct SupportedBoomMode {
  // swing: the boom's deformation stores under half the mode's potential energy (the boom turning on
  // the wires' spring); axial: over half its kinetic energy in the axial motion; bending: the rest.
  // a_frame: over half its kinetic energy in an A-frame pinned to the deck (rocking on its backstays).
  enum class Kind { swing, bending, axial, a_frame };
  double hz = 0.0;
  Kind kind = Kind::bending;
  double strain_share = 0.0;  // share of the mode's potential energy in the boom's deformation [-]
  double axial_share = 0.0;   // share of its kinetic energy in the axial motion [-]
  double a_frame_share = 0.0;  // share of its kinetic energy in the A-frame's rocking (0 without one) [-]
  int bending_order = 0;     // n of the n-th bending mode (0 for the others)
  double pinned_pinned_hz = 0.0;  // the simply supported span's n-th bending frequency (0 for the others)
};
std::string_view to_string(SupportedBoomMode::Kind kind);  // "swing", "bending", "axial", "A-frame"

struct SupportedBoomModes {
  int elements = 0;
  double luffing_tension = 0.0;  // the luffing wires' static tension, all together [N]
  bool a_frame = false;          // the A-frame stands on its own pin (its rocking is a coordinate)
  double backstay_tension = 0.0;  // then the backstays' static tension, all together [N]
  std::vector<SupportedBoomMode> modes;
};

// The lowest `count` modes of the boom of a pinned scene on `elements` elements; nullopt for a
// boom clamped to the deck (its modes are the clamped-free beam's). Throws solve::SolverFailure
// when the static equilibrium is not found (a slack luffing wire, named) and std::runtime_error
// when the eigenvalue solver fails or the linearised mass is not positive definite.
std::optional<SupportedBoomModes> supported_boom_modes(const scene::Scene& scene, int elements, int count);

}  // namespace ffrf::study
