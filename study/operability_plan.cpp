// What an operability table will run, before anything runs (see operability.hpp): each cell's sea
// (physical or not, band, components, repetition), its models, the verified cells and the warnings.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "study/operability.hpp"

namespace ffrf::study {

std::size_t OperabilityPlan::physical_cells() const {
  std::size_t n = 0;
  for (const CellSea& sea : seas) n += sea.physical() ? 1 : 0;
  return n;
}

std::size_t OperabilityPlan::records(int seeds) const {
  return (physical_cells() + verified.size()) * static_cast<std::size_t>(seeds);
}

OperabilityPlan plan_operability(const scene::Scene& scene, const OperabilityRequest& request, modal::ModeCache* modes) {
  validate(request);
  OperabilityPlan plan;
  plan.cells = sea_cells(request);
  std::vector<std::size_t> physical;
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    const SeaCell& cell = plan.cells[c];
    plan.seas.push_back(cell_sea(scene, cell, request));
    if (!plan.seas.back().physical()) {
      plan.recommended.emplace_back();
      plan.converged.emplace_back();
      continue;
    }
    physical.push_back(c);
    plan.recommended.push_back(recommended_model(scene, cell, request, modes));
    plan.converged.push_back(converged_model(scene, request, plan.recommended.back()));
  }
  if (physical.empty()) {
    const SeaCell& first = plan.cells.front();
    throw std::invalid_argument(fmt::format("operability: no cell of the grid is a sea that can exist ({}; every cell is "
                                            "steeper than DNV-RP-C205's breaking limit): lower Hs or raise Tp",
                                            not_physical_reason(first.significant_height, first.peak_period,
                                                                plan.seas.front().steepness)));
  }
  for (std::size_t i : verified_cells(physical.size(), request.verify_cells)) plan.verified.push_back(physical[i]);
  if (const std::string repeat = repetition_warning(plan, request); !repeat.empty()) plan.warnings.push_back(repeat);
  if (scene.sea && (scene.sea->frequency_min > 0.0 || scene.sea->frequency_max > 0.0)) {
    plan.warnings.push_back(fmt::format(
        "the scene's wave band [{:g}, {:g}] rad/s belongs to its own sea (Tp = {:g} s) and is not used: each cell's "
        "records keep the band of its own spectrum that holds {:g} % of its variance m0",
        scene.sea->frequency_min, scene.sea->frequency_max, scene.sea->peak_period, 100.0 * request.variance_share));
  }
  return plan;
}

std::string repetition_warning(const OperabilityPlan& plan, const OperabilityRequest& request) {
  const CellSea* fewest = nullptr;
  const SeaCell* where = nullptr;
  std::size_t repeating = 0, physical = 0;
  for (std::size_t c = 0; c < plan.cells.size(); ++c) {
    const CellSea& sea = plan.seas[c];
    if (!sea.physical()) continue;
    ++physical;
    if (!sea.repeats()) continue;
    ++repeating;
    if (!fewest || sea.independent_wave_cycles < fewest->independent_wave_cycles) {
      fewest = &sea;
      where = &plan.cells[c];
    }
  }
  if (!fewest) return {};
  return fmt::format(
      "the synthesized sea repeats within the {:g}-s record in {} of {} cells ({} wave components each): at Hs = {:g} m, "
      "Tp = {:g} s it repeats every {:.4g} s (2π/Δω, Δω = {:.4g} rad/s over the band [{:.3g}, {:.3g}] rad/s), so the "
      "record is {:.1f} repeats of the same waves and its statistics rest on about {:.0f} independent wave cycles "
      "(one repeat over Tz = {:.3g} s), not on the record length; use {} or more components, or 0 (Δω = 2π / record "
      "length: a sea that never repeats)",
      request.duration, repeating, physical, request.components, where->significant_height, where->peak_period,
      fewest->repeat_period, fewest->frequency_step, fewest->band.lower, fewest->band.upper, fewest->record_repeats,
      fewest->independent_wave_cycles, fewest->zero_crossing_period,
      static_cast<long>(std::ceil(request.components * fewest->record_repeats)));
}

}  // namespace ffrf::study
