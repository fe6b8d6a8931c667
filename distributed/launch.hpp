// Was this process started by a parallel launcher, and as one of how many? Read from the
// environment the launchers set before the program starts, without calling MPI: Open MPI's
// mpirun/mpiexec (OMPI_COMM_WORLD_SIZE/RANK), any PMIx launcher (PMIX_RANK: mpirun, `srun
// --mpi=pmix`), PMI-1/2 launchers (PMI_RANK/PMI_SIZE: MPICH's hydra, `srun --mpi=pmi2`) and
// Slurm's srun (SLURM_STEP_NUM_TASKS > 1 with SLURM_PROCID). A plain `./prog`, and the batch
// script of an sbatch job (one task, no step of its own), are not launched: they run serially
// without initialising MPI, which singleton MPI_Init cannot be trusted to do in every container.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace ffrf::distributed {

struct LaunchInfo {
  bool launched = false;  // started by a launcher: MPI must be initialised
  int size = 1;           // processes the launcher started (1 when unknown or not launched)
  int rank = 0;           // this process's rank as the launcher numbers it (0 when unknown)
  std::string launcher;   // "mpirun", "PMIx", "PMI", "srun" or "none"
};

// A look-up of an environment variable (std::nullopt when unset); tests pass a fake environment.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;

LaunchInfo detect_launch(const Environment& environment);
LaunchInfo detect_launch();  // from this process's environment

}  // namespace ffrf::distributed
