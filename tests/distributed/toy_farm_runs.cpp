// Toy-farm runs for the process tests (see toy_farm_runs.hpp).
#include "toy_farm_runs.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fstream>
#include <ostream>
#include <sstream>
#include <thread>

namespace ffrf::test {

void PrintTo(const Launcher& launcher, std::ostream* os) { *os << launcher.name; }

std::string mpirun_unavailable_reason() {
  const std::string mpiexec = FFRF_MPIEXEC;
  if (mpiexec.empty()) return "this build has no MPI (FFRF_WITH_MPI=OFF)";
  if (::access(mpiexec.c_str(), X_OK) != 0) return "mpirun (" + mpiexec + ") is not installed";
  return "";
}

ChildSpec toy_farm(const Launcher& launcher, const std::vector<std::string>& arguments) {
  ChildSpec spec;
  if (launcher.processes > 0) {
    spec.argv = {FFRF_MPIEXEC, "--oversubscribe", "-np", std::to_string(launcher.processes)};
    spec.environment = {{"OMPI_ALLOW_RUN_AS_ROOT", "1"}, {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"}};
  }
  // Constructed in place: push_back(TOY_FARM) moves a temporary std::string, and GCC 12 at -O3 (with
  // the precompiled headers' inlining context) then reports a false -Warray-bounds on the move of a
  // long path out of the temporary's 32-byte object.
  spec.argv.emplace_back(TOY_FARM);
  spec.argv.insert(spec.argv.end(), arguments.begin(), arguments.end());
  return spec;
}

RunOutput run_toy_farm(const Launcher& launcher, const std::vector<std::string>& arguments,
                       const std::filesystem::path& scratch) {
  return run_child(toy_farm(launcher, arguments), scratch, std::chrono::minutes(3));
}

std::map<std::size_t, int> traced_computations(const std::filesystem::path& directory) {
  std::map<std::size_t, int> count;
  if (!std::filesystem::exists(directory)) return count;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    std::istringstream lines(read_text(entry.path()));
    std::size_t index = 0;
    while (lines >> index) ++count[index];
  }
  return count;
}

std::set<int> ranks_in_timing(const std::filesystem::path& timing_csv) {
  std::istringstream lines(read_text(timing_csv));
  std::string line;
  std::getline(lines, line);  // header: index,rank,wall_s,resumed
  std::set<int> ranks;
  while (std::getline(lines, line)) {
    const std::size_t first = line.find(',');
    ranks.insert(std::stoi(line.substr(first + 1, line.find(',', first + 1) - first - 1)));
  }
  return ranks;
}

std::vector<std::size_t> journaled_indices(const std::filesystem::path& journal) {
  const std::string text = read_text(journal);
  std::vector<std::size_t> indices;
  std::size_t start = text.find('\n');  // after the header
  while (start != std::string::npos && start + 1 < text.size()) {
    const std::size_t end = text.find('\n', start + 1);
    if (end == std::string::npos) break;  // a torn last line
    const std::string line = text.substr(start + 1, end - start - 1);
    const std::size_t tab = line.find('\t');
    indices.push_back(std::stoul(line.substr(tab + 1, line.find('\t', tab + 1) - tab - 1)));
    start = end;
  }
  return indices;
}

bool wait_until_unlocked(const std::filesystem::path& journal, std::chrono::milliseconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (true) {
    const int fd = ::open(journal.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return true;
    const bool free = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
    ::close(fd);
    if (free) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace ffrf::test
