// Test helper: runs of the toy farm (toy_farm.cpp) alone or under mpirun, and what the tests read
// back independently of the engine: the trace files (which process computed which task), the
// ranks in timing.csv, the complete lines of a journal, whether its lock is free.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace ffrf::test {

// How the toy farm is started: alone (processes == 0) or by mpirun with that many processes.
struct Launcher {
  std::string name;
  int processes = 0;
};

void PrintTo(const Launcher& launcher, std::ostream* os);

// Empty when mpirun can be used; otherwise why not (for GTEST_SKIP).
std::string mpirun_unavailable_reason();

// The command line and environment (Open MPI allowed to run as root, as in CI containers).
ChildSpec toy_farm(const Launcher& launcher, const std::vector<std::string>& arguments);

RunOutput run_toy_farm(const Launcher& launcher, const std::vector<std::string>& arguments,
                       const std::filesystem::path& scratch);

// Task index -> how many times it was computed, over every trace file in `directory`.
std::map<std::size_t, int> traced_computations(const std::filesystem::path& directory);

// The distinct values of timing.csv's rank column.
std::set<int> ranks_in_timing(const std::filesystem::path& timing_csv);

// The task indices of the journal's complete ('\n'-terminated) record lines, header excluded.
std::vector<std::size_t> journaled_indices(const std::filesystem::path& journal);

// Waits until no process holds the journal's lock; false if one still does after `limit`.
bool wait_until_unlocked(const std::filesystem::path& journal, std::chrono::milliseconds limit);

}  // namespace ffrf::test
