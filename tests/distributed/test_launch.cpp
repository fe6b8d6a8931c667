// Launcher detection on fake environments: the variables each launcher documents (Open MPI's
// mpirun, PMIx, PMI-1/2, Slurm's srun) make a launched process; a plain shell or the batch script of
// an sbatch job (Slurm sets SLURM_PROCID=0 and SLURM_NTASKS there, but no multi-task step) do not.
#include <gtest/gtest.h>

#include <map>

#include "distributed/launch.hpp"

namespace ffrf::distributed {
namespace {

LaunchInfo detect(const std::map<std::string, std::string>& variables) {
  return detect_launch([&](const std::string& name) -> std::optional<std::string> {
    const auto it = variables.find(name);
    if (it == variables.end()) return std::nullopt;
    return it->second;
  });
}

TEST(Launch, APlainProgramIsNotLaunched) {
  const LaunchInfo info = detect({{"HOME", "/root"}});
  EXPECT_FALSE(info.launched);
  EXPECT_EQ(info.size, 1);
  EXPECT_EQ(info.launcher, "none");
}

TEST(Launch, OpenMpiMpirun) {
  const LaunchInfo info = detect({{"OMPI_COMM_WORLD_SIZE", "3"}, {"OMPI_COMM_WORLD_RANK", "1"}, {"PMIX_RANK", "1"}});
  EXPECT_TRUE(info.launched);
  EXPECT_EQ(info.size, 3);
  EXPECT_EQ(info.rank, 1);
  EXPECT_EQ(info.launcher, "mpirun");
}

TEST(Launch, PmixAndPmiLaunchers) {
  EXPECT_TRUE(detect({{"PMIX_RANK", "0"}}).launched);
  const LaunchInfo pmi = detect({{"PMI_RANK", "2"}, {"PMI_SIZE", "4"}});
  EXPECT_TRUE(pmi.launched);
  EXPECT_EQ(pmi.size, 4);
  EXPECT_EQ(pmi.rank, 2);
}

TEST(Launch, SrunWithSeveralTasks) {
  const LaunchInfo info = detect({{"SLURM_STEP_NUM_TASKS", "8"}, {"SLURM_PROCID", "5"}, {"SLURM_NTASKS", "8"}});
  EXPECT_TRUE(info.launched);
  EXPECT_EQ(info.size, 8);
  EXPECT_EQ(info.rank, 5);
  EXPECT_EQ(info.launcher, "srun");
}

TEST(Launch, AnSbatchScriptOrASingleTaskStepRunsSerially) {
  EXPECT_FALSE(detect({{"SLURM_PROCID", "0"}, {"SLURM_NTASKS", "4"}, {"SLURM_JOB_ID", "42"}}).launched);
  EXPECT_FALSE(detect({{"SLURM_STEP_NUM_TASKS", "1"}, {"SLURM_PROCID", "0"}}).launched);
}

TEST(Launch, GarbageValuesAreIgnored) {
  EXPECT_FALSE(detect({{"OMPI_COMM_WORLD_SIZE", "three"}}).launched);
  EXPECT_FALSE(detect({{"PMI_RANK", ""}}).launched);
}

}  // namespace
}  // namespace ffrf::distributed
