// Launcher detection from the environment (see launch.hpp).
#include "distributed/launch.hpp"

#include <charconv>
#include <cstdlib>

namespace ffrf::distributed {
namespace {

std::optional<int> integer(const Environment& environment, const std::string& name) {
  const std::optional<std::string> text = environment(name);
  if (!text || text->empty()) return std::nullopt;
  int value = 0;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end != text->data() + text->size() || value < 0) return std::nullopt;
  return value;
}

}  // namespace

LaunchInfo detect_launch(const Environment& environment) {
  LaunchInfo info;
  if (const auto size = integer(environment, "OMPI_COMM_WORLD_SIZE")) {
    info = {true, std::max(*size, 1), integer(environment, "OMPI_COMM_WORLD_RANK").value_or(0), "mpirun"};
  } else if (const auto pmix_rank = integer(environment, "PMIX_RANK")) {
    // PMIx does not put the size in the environment; MPI_Comm_size tells it after MPI_Init.
    info = {true, 1, *pmix_rank, "PMIx"};
  } else if (const auto pmi_rank = integer(environment, "PMI_RANK")) {
    info = {true, std::max(integer(environment, "PMI_SIZE").value_or(1), 1), *pmi_rank, "PMI"};
  } else if (const auto step_tasks = integer(environment, "SLURM_STEP_NUM_TASKS");
             step_tasks && *step_tasks > 1 && integer(environment, "SLURM_PROCID")) {
    info = {true, *step_tasks, *integer(environment, "SLURM_PROCID"), "srun"};
  } else {
    info.launcher = "none";
  }
  return info;
}

LaunchInfo detect_launch() {
  return detect_launch([](const std::string& name) -> std::optional<std::string> {
    const char* value = std::getenv(name.c_str());
    if (value == nullptr) return std::nullopt;
    return std::string(value);
  });
}

}  // namespace ffrf::distributed
