// Sea-state cells, the boom model per cell and one record's run (see operability.hpp).
#include "study/operability.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "solve/time_reached.hpp"
#include "distributed/stable_hash.hpp"
#include "hydro/wave_spectrum.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_key.hpp"
#include "scene/scene_loader.hpp"
#include "study/error_measure.hpp"
#include "study/recommend.hpp"
#include "study/recommend_reasoning.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {
namespace {

constexpr double band_tail = 0.01;  // the excitation band holds all but 1 % of the sea's variance

std::string_view heading_name(hydro::WaveHeading heading) {
  return heading == hydro::WaveHeading::head ? "head" : "following";
}

}  // namespace

std::string SeaCell::key() const {
  return fmt::format("Hs={:.17g} Tp={:.17g} heading={}", significant_height, peak_period, heading_name(heading));
}

std::string_view to_string(CellStatus status) {
  switch (status) {
    case CellStatus::ok: return "ok";
    case CellStatus::failed: return "failed";
    case CellStatus::not_physical: return "not_physical";
  }
  return "?";
}

std::string CellModel::label() const {
  return fmt::format("{}, {} rtol {:.0e}", choice.label(), solve::to_string(integrator), relative_tolerance);
}

hydro::WaveHeading parse_heading(std::string_view name) {
  if (name == "following") return hydro::WaveHeading::following;
  if (name == "head") return hydro::WaveHeading::head;
  throw SettingError(Setting::headings, std::string(name), "not a heading (following or head)");
}

void validate(const OperabilityRequest& r) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (r.significant_heights.empty() || r.peak_periods.empty() || r.headings.empty()) bad("operability: an empty grid axis");
  for (double hs : r.significant_heights) {
    if (!(hs > 0.0 && hs <= 20.0)) bad(fmt::format("operability: Hs = {} m out of range (valid range (0, 20] m)", hs));
  }
  for (double tp : r.peak_periods) {
    if (!(tp >= 2.0 && tp <= 30.0)) bad(fmt::format("operability: Tp = {} s out of range (valid range [2, 30] s)", tp));
  }
  if (r.components < 0 || r.components > 100000) {
    bad(fmt::format("operability: {} wave components (valid range [0, 100000], 0: a sea that never repeats)", r.components));
  }
  if (!(r.variance_share > 0.5 && r.variance_share < 1.0)) {
    bad(fmt::format("operability: wave band variance share {} out of range (valid range (0.5, 1))", r.variance_share));
  }
  if (r.seeds < 1 || r.seeds > 1000) bad(fmt::format("operability: {} seeds per cell (valid range [1, 1000])", r.seeds));
  if (!(r.duration > 0.0 && r.duration <= 86400.0)) {
    bad(fmt::format("operability: record length {} s out of range (valid range (0, 86400] s)", r.duration));
  }
  if (!(r.peak_enhancement >= 1.0 && r.peak_enhancement <= 20.0)) {
    bad(fmt::format("operability: peak enhancement {} out of range (valid range [1, 20])", r.peak_enhancement));
  }
  if (!(r.tolerance > 0.0 && r.tolerance < 1.0)) bad(fmt::format("operability: tolerance {} (valid range (0, 1))", r.tolerance));
  if (r.verify_cells < 0) bad(fmt::format("operability: {} verified cells (valid range [0, cells])", r.verify_cells));
  if (r.converged_elements < 2 || r.converged_elements > 256) {
    bad(fmt::format("operability: converged model with {} elements (valid range [2, 256])", r.converged_elements));
  }
  validate(r.criteria);
}

std::vector<SeaCell> sea_cells(const OperabilityRequest& request) {
  std::vector<SeaCell> cells;
  for (hydro::WaveHeading heading : request.headings) {
    for (double tp : request.peak_periods) {
      for (double hs : request.significant_heights) cells.push_back({hs, tp, heading});
    }
  }
  return cells;
}

std::vector<std::size_t> verified_cells(std::size_t cells, int count) {
  std::vector<std::size_t> chosen;
  const std::size_t n = std::min(cells, static_cast<std::size_t>(std::max(count, 0)));
  for (std::size_t i = 0; i < n; ++i) chosen.push_back((2 * i + 1) * cells / (2 * n));  // the middles of n equal blocks
  return chosen;
}

OperabilityCriteria resolve_criteria(const scene::Scene& scene, const OperabilityCriteria& criteria) {
  OperabilityCriteria resolved = criteria;
  if (resolved.daf_limit == 0.0) {
    if (!scene.has_cargo()) throw std::invalid_argument("operability: the scene has no cargo (a lift needs one)");
    resolved.daf_limit = offshore_daf_limit(scene.cargo->mass / 1000.0);
  }
  if (resolved.allowable_stress == 0.0 && scene.boom.allowable_stress) resolved.allowable_stress = *scene.boom.allowable_stress;
  if (scene.boom.mount && scene.boom.mount->pinned) {
    // A pin carries no moment: the boom's load is its fibre stress, which needs its allowable value.
    resolved.root_moment_capacity = std::numeric_limits<double>::infinity();
    if (!(resolved.allowable_stress > 0.0)) {
      throw scene::SceneError({scene::SceneProblem{scene.file, 0, 0, std::string(scene::scene_key("boom.allowable_stress")), "",
                               "operability judges a pinned boom by its peak fibre stress: give the allowable stress of its "
                               "extreme fibre (e.g. boom.allowable_stress = \"235 MPa\"; valid range [1, 5000] MPa)"}});
    }
  }
  return resolved;
}

std::uint64_t record_seed(const SeaCell& cell, int index) {
  // 31 bits: the range of wave.seed, [0, 2^31 − 1].
  return distributed::StableHash().add_field(cell.key()).add_field(fmt::format("seed={}", index)).value() & 0x7fffffffULL;
}

hydro::WaveSpectrum cell_spectrum(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request) {
  scene::IrregularSea sea = scene.sea && scene.sea->spectrum != scene::SeaSpectrum::components ? *scene.sea : scene::IrregularSea{};
  sea.spectrum = scene::SeaSpectrum::jonswap;
  sea.significant_height = cell.significant_height;
  sea.peak_period = cell.peak_period;
  sea.peak_enhancement = request.peak_enhancement;
  return scene::sea_spectrum(sea);
}

CellSea cell_sea(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request) {
  const double ramp_periods = scene.sea && scene.sea->spectrum != scene::SeaSpectrum::components ? scene.sea->ramp_periods
                                                                                                 : scene::IrregularSea{}.ramp_periods;
  return cell_sea(cell_spectrum(scene, cell, request), scene.environment.gravity, request.duration,
                  ramp_periods * cell.peak_period, request.components, request.variance_share);
}

scene::Scene record_scene(const scene::Scene& scene, const SeaCell& cell, std::uint64_t seed, const OperabilityRequest& request) {
  scene::IrregularSeaState sea;
  sea.spectrum = "jonswap";
  sea.significant_height = cell.significant_height;
  sea.peak_period = cell.peak_period;
  sea.peak_enhancement = request.peak_enhancement;
  sea.heading = cell.heading;
  sea.seed = seed;
  sea.duration = request.duration;
  // in_irregular_sea keeps the base sea's band and component count: the cell's own band (not the
  // scene's, which belongs to its own Tp) and the request's count.
  const hydro::FrequencyBand band = hydro::variance_band(cell_spectrum(scene, cell, request), request.variance_share);
  scene::Scene base = scene;
  if (!base.sea || base.sea->spectrum == scene::SeaSpectrum::components) base.sea = scene::IrregularSea{};
  base.wave.reset();
  base.sea->component_count = request.components;
  base.sea->frequency_min = band.lower;
  base.sea->frequency_max = band.upper;
  return scene::in_irregular_sea(base, sea);
}

namespace {

// The reasoning's first kept BDF candidate for the cell's sea seen as a regular wave at the top of its
// energy band: the model when the probe below cannot be run.
CellModel reasoned_model(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request,
                         modal::ModeCache* modes, double top) {
  scene::Scene reasoning_scene = scene;
  reasoning_scene.sea.reset();
  reasoning_scene.wave = scene::Wave{cell.significant_height, 2.0 * std::numbers::pi / top, cell.heading, 2.0};
  const RecommendReasoning reasoning = reason_about(reasoning_scene, request.tolerance, judged_outputs(reasoning_scene));
  CellModel model;
  model.relative_tolerance = reasoning.relative_tolerance;
  model.excitation_top = top;
  model.dynamic_modes = reasoning.dynamic_modes;
  model.euler_load = reasoning.euler_load;
  for (const Candidate& candidate : candidate_ladder(reasoning_scene, reasoning, modes)) {
    if (candidate.prune_reason.empty() && candidate.integrator != solve::Integrator::arkode) {
      model.choice = candidate.choice;
      model.integrator = candidate.integrator;
      return model;
    }
  }
  throw std::runtime_error(fmt::format("operability: recommend's reasoning kept no model for {}", cell.key()));
}

}  // namespace

double probe_duration(const SeaCell& cell, const OperabilityRequest& request) {
  return std::min(request.duration, probe_peak_periods * cell.peak_period);
}

CellModel recommended_model(const scene::Scene& scene, const SeaCell& cell, const OperabilityRequest& request,
                            modal::ModeCache* modes) {
  // The upper edge of the sea's energy band (reported): the highest frequency the cell excites with
  // more than band_tail/2 of its variance above it.
  const hydro::WaveSpectrum spectrum = hydro::jonswap(cell.significant_height, cell.peak_period, request.peak_enhancement);
  const double top = hydro::energy_band(spectrum, band_tail).upper;
  // recommend on the probe record: its cheapest passing model by solver work at the model-choice rtol.
  OperabilityRequest probe_request = request;
  probe_request.duration = probe_duration(cell, request);
  const scene::Scene probe = record_scene(scene, cell, record_seed(cell, 0), probe_request);
  RecommendRequest recommend_request;
  recommend_request.tolerance = request.tolerance;
  recommend_request.duration = probe_request.duration;
  std::optional<Recommendation> rec;
  try {
    rec = recommend(probe, recommend_request, {}, modes);
  } catch (const solve::SolverFailure&) {
    return reasoned_model(scene, cell, request, modes, top);  // the probe's reference failed: no verification
  }
  CellModel model;
  model.relative_tolerance = rec->reasoning.relative_tolerance;
  model.excitation_top = top;
  model.dynamic_modes = rec->reasoning.dynamic_modes;
  model.euler_load = rec->reasoning.euler_load;
  const scene::Stiffening stiffening = rec->reference_scene.boom.stiffening;
  if (rec->chosen) {
    const Candidate& chosen = rec->candidates[*rec->chosen];
    model.choice = chosen.choice;
    model.integrator = chosen.integrator;
  } else {  // nothing cheaper passes: the reference's model
    model.choice = rec->reference.choice;
    model.integrator = rec->reference.settings.kind;
    model.relative_tolerance = rec->reference.settings.relative_tolerance;
  }
  model.choice.stiffening = model.choice.stiffening.value_or(stiffening);
  return model;
}

CellModel converged_model(const scene::Scene& scene, const OperabilityRequest& request, const CellModel& recommended) {
  CellModel model = recommended;
  model.choice = scene::BoomChoice{};
  model.choice.kind = scene::BoomKind::nodal;
  model.choice.elements = request.converged_elements;
  model.choice.stiffening = physics_stiffening(scene, request.tolerance);
  model.integrator = solve::Integrator::cvode;
  model.relative_tolerance = request.tolerance / 1000.0;
  return model;
}

SeedExtremes run_record(const scene::Scene& scene, const SeaCell& cell, int seed_index, const CellModel& model,
                        const OperabilityRequest& request, modal::ModeCache* modes, std::atomic<double>* time_reached) {
  const scene::Scene record = record_scene(scene, cell, record_seed(cell, seed_index), request);
  const solve::TimeReachedSink progress(time_reached);
  DynamicsRequest dynamics;
  dynamics.integrator = model.integrator;
  dynamics.relative_tolerance = dynamics.absolute_tolerance = model.relative_tolerance;
  dynamics.duration = request.duration;
  const multibody::RunSettings settings = integrator_settings(record, dynamics);
  const ModelRun run = run_model(record, model.choice, settings, modes);
  SeedRecords records;
  records.time = run.result.time;
  for (const multibody::CraneOutputs& o : run.result.samples) {
    records.tension.push_back(o.wire_tension);
    records.cargo_heave.push_back(o.cargo.y());
    records.root_moment.push_back(o.joint_reaction.z());
    records.root_axial_force.push_back(o.root_axial_force);
    records.peak_stress.push_back(o.boom_peak_stress);
  }
  const multibody::CraneOutputs& at_rest = run.static_outputs();
  records.static_tension = at_rest.wire_tension;
  records.static_root_moment = at_rest.joint_reaction.z();
  records.static_peak_stress = at_rest.boom_peak_stress;
  SeedExtremes extremes = seed_extremes(records, scene::wave_ramp_duration(record));
  extremes.work = run.work();
  extremes.rhs_evaluations = static_cast<double>(run.result.stats.function_evaluations);
  return extremes;
}

}  // namespace ffrf::study
