// Cross-key physics checks of a loaded scene, so a scene that cannot float or hang fails before any solve: what no single key's range can say. Each
// finding names the keys involved, their values and the physical reason with its numbers:
//  * attachment points: the boom root B over the hull, between the keel and a pedestal of half the
//    hull length above the deck; the hook C on or inside the cargo box;
//  * G1 inside the hull, below the deck; each radius of gyration within its body's reach;
//  * a floating hull needs gravity (buoyancy ρ g V) and a surge spring (nothing else restores surge);
//  * the loaded hull floats (ρ L B D above its mass) in water deeper than its draft;
//  * static stability in pitch with the load hanging at the boom tip (its weight acts at the
//    suspension point): GM_L = KB + BM_L − KG > 0, KB = T/2, BM_L = L²/(12 T) for a box; the deck
//    ends above water and the cargo above water at the trim the load moment gives (linear
//    hydrostatics, θ = M / (ρ g V GM_L));
//  * the wave: steepness H/λ < 1/7 (Michell's breaking limit), H < 0.78 d in finite depth
//    (McCowan's depth-limited breaking), a warning where linear theory leaves its range in shallow
//    water (kd < π/10 or Ursell number H λ² / d³ > 26);
//  * at most max_output_samples output intervals in the simulated time;
//  * a warning for a hull lighter than 1 % of what it carries (a mass in t written as kg?).
// References: Faltinsen, Sea Loads on Ships and Offshore Structures (1990) §2 (waves, breaking) and
// §4 (hydrostatics of a box); Dean & Dalrymple, Water Wave Mechanics (1991) (Ursell number).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ffrf::scene {

// Most output samples of one run (duration / output interval): a sample and its CSV row take about
// half a kilobyte, so a run stays within a few hundred megabytes.
inline constexpr double max_output_samples = 1e6;

struct SceneFinding {
  bool error = true;              // false: a warning (the scene runs; it may not be what was meant)
  std::vector<std::string> keys;  // the dotted keys involved; the first is where it is reported
  std::string message;            // the physical reason with its numbers and the valid range
};

// Every finding of a scene whose keys are each valid on their own.
std::vector<SceneFinding> physics_findings(const Scene& scene);

// The loaded hull at rest by linear hydrostatics of the box (a hull crane whose hull floats), as the
// checks use it: mean draft T = Δ/(ρ L B), GM_L with the cargo's weight at the boom tip, the trim
// θ = M / (Δ GM_L) from the weights' moment M about mid-length (the centre of flotation), the
// deck edge's sinkage (L/2)|tan θ| and the cargo's lowest point above still water.
struct RestingHydrostatics {
  double displacement = 0.0;        // Δ: hull + boom + cargo [kg]
  double draft = 0.0;               // T [m]
  double metacentric_height = 0.0;  // GM_L [m]
  double load_moment = 0.0;         // M [kg m], > 0: bow down
  double trim = 0.0;                // θ [rad], > 0: bow down
  double deck_sinkage = 0.0;        // [m]
  double cargo_bottom = 0.0;        // above still water [m]
};
RestingHydrostatics resting_hydrostatics(const Scene& scene);

}  // namespace ffrf::scene
