// Work and memory limits of a run (see work_limits.hpp).
#include "study/work_limits.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fem/mesh.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::study {
namespace {
constexpr double gibibyte = 1024.0 * 1024.0 * 1024.0;
}  // namespace

int elastic_coordinates(const scene::BoomChoice& choice) {
  switch (choice.kind) {
    case scene::BoomKind::rigid: return 0;
    case scene::BoomKind::nodal: return fem::clamped_free_dof_count(choice.elements);
    case scene::BoomKind::modal: return choice.modes + (choice.static_modes ? 6 : 0);
  }
  return 0;
}

double newton_matrix_bytes(int elastic) {
  const double state = 2.0 * (9.0 + static_cast<double>(elastic)) + 3.0;
  return 3.0 * state * state * static_cast<double>(sizeof(double));
}

int max_nodal_elements() {
  const double state = std::sqrt(memory_limit_bytes / (3.0 * sizeof(double)));
  return static_cast<int>(std::floor(((state - 3.0) / 2.0 - 9.0) / 3.0));
}

void check_run_memory(const scene::BoomChoice& choice) {
  const double bytes = newton_matrix_bytes(elastic_coordinates(choice));
  if (bytes <= memory_limit_bytes) return;
  throw SettingError(
      Setting::elements, fmt::format("{}", choice.elements),
      fmt::format("{} has {} elastic coordinates: the integrator's dense Newton matrices would need {:.3g} GiB, more "
                  "than the limit of {:g} GiB (valid range [1, {}] elements for a nodal boom; a modal boom has a "
                  "few coordinates on any mesh)",
                  choice.label(), elastic_coordinates(choice), bytes / gibibyte, memory_limit_bytes / gibibyte,
                  max_nodal_elements()));
}

}  // namespace ffrf::study
