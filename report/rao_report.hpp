// What `ffrf rao` writes: per model a CSV of the RAOs (period, ω, then amplitude and phase of every
// output per metre of wave amplitude; column names carry units), the natural modes CSV, the
// Markdown report (provenance, coupled natural frequencies and damping ratios side by side, the
// largest RAOs, the resonance peaks and the sea's significant responses (report/rao_resonance.hpp),
// the time-domain check's verdict when it ran), the JSON summary; the charts are
// report/rao_charts.hpp's. Formatting only.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "study/rao.hpp"
#include "study/rao_check.hpp"

namespace ffrf::report {

struct RaoContext {
  std::string scene_file;
  std::string scene_name;
  double wall_seconds = 0.0;  // the whole command
};

// "rigid", "nodal_N16", "modal_k2_static_N16": the model's part of a file name.
std::string model_slug(const scene::BoomChoice& choice);
// rao_<slug>.csv: period_s, angular_frequency_rad_per_s, then OUTPUT_amplitude_<unit per m>, OUTPUT_phase_deg.
std::string rao_csv(const study::RaoResult& result, std::size_t model);
// model, mode, angular_frequency_rad_per_s, period_s, damping_ratio, dominant
std::string natural_modes_csv(const study::RaoResult& result);
// The time-domain check: model, period_s, output, rao_amplitude, time_domain_amplitude, deviation, ...
std::string time_domain_check_csv(const std::vector<study::TimeDomainCheck>& checks);

std::string rao_markdown(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks,
                         const RaoContext& context, bool charts);
std::string rao_json(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks, const RaoContext& context);
// The terminal summary: natural modes per model and the check's verdict.
std::string rao_text(const study::RaoResult& result, const std::vector<study::TimeDomainCheck>& checks, const RaoContext& context);

}  // namespace ffrf::report
