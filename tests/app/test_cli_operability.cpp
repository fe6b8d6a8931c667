// `ffrf operability` on the distributed engine, as users run it: serially, with threads, under
// `mpirun --oversubscribe -np 3`, killed mid-way and rerun. Independent facts: the table (timing
// columns `*_s` removed) is byte-identical whatever the number of processes and threads, and after a
// kill and a resume; the killed run wrote no table and the rerun computed only the records missing
// from the journal (counted from the journal's own lines); bad axes are refused with the option named;
// a grid with a breaking cell names it not physical and exits 0, a sea that repeats within the record
// is warned about, and report.md's command reproduces the run.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../distributed/child_process.hpp"
#include "../distributed/scratch_directory.hpp"

namespace ffrf::test {
namespace {

const std::string ffrf = FFRF_BINARY_DIR "/app/ffrf";
const std::string scene = FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml";
// 3 × 2 cells × 2 seeds + 1 verified cell × 2 seeds = 14 irregular records of 200 s (40 components).
const std::vector<std::string> grid = {"--hs", "0.5:1.5:3", "--tp", "7:8:2", "--seeds", "2", "--duration", "200",
                                       "--components", "40", "--verify", "1", "--cargo-motion-limit", "3"};

std::string mpirun_unavailable_reason() {
  const std::string mpiexec = FFRF_MPIEXEC;
  if (mpiexec.empty()) return "this build has no MPI (FFRF_WITH_MPI=OFF)";
  if (::access(mpiexec.c_str(), X_OK) != 0) return "mpirun (" + mpiexec + ") is not installed";
  return "";
}

ChildSpec operability(int processes, const std::filesystem::path& out, const std::vector<std::string>& more = {}) {
  ChildSpec spec;
  if (processes > 0) {
    spec.argv = {FFRF_MPIEXEC, "--oversubscribe", "-np", std::to_string(processes)};
    spec.environment = {{"OMPI_ALLOW_RUN_AS_ROOT", "1"}, {"OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1"}};
  }
  spec.argv.insert(spec.argv.end(), {ffrf, "operability", scene, "--out", out.string()});
  spec.argv.insert(spec.argv.end(), grid.begin(), grid.end());
  spec.argv.insert(spec.argv.end(), more.begin(), more.end());
  return spec;
}

RunOutput run(int processes, const std::filesystem::path& out, const ScratchDirectory& dir,
              const std::vector<std::string>& more = {}) {
  return run_child(operability(processes, out, more), dir.path(), std::chrono::minutes(10));
}

// operability.csv without its timing columns (the header names them `*_s`).
std::string table_without_timing(const std::filesystem::path& csv) {
  std::istringstream lines(read_text(csv));
  std::string line, table;
  std::vector<bool> timing;
  bool header = true;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) {
        fields.push_back(field);
        field.clear();
      } else {
        field += c;
      }
    }
    fields.push_back(field);
    if (header) {
      for (const std::string& name : fields) timing.push_back(name.size() > 2 && name.substr(name.size() - 2) == "_s" && name != "hs_m");
      header = false;
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i < timing.size() && !timing[i]) table += fields[i] + ",";
    }
    table += "\n";
  }
  return table;
}

std::size_t journaled_records(const std::filesystem::path& journal) {
  const std::string text = std::filesystem::exists(journal) ? read_text(journal) : std::string();
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines > 0 ? lines - 1 : 0;  // the header
}

TEST(CliOperability, SameTableSeriallyWithThreadsAndUnderMpirunNp3) {
  ScratchDirectory dir;
  const RunOutput serial = run(0, dir / "serial", dir, {"--threads", "1"});
  ASSERT_EQ(serial.end.exit_code, 0) << serial.err;
  const std::string reference = table_without_timing(dir / "serial/operability.csv");
  EXPECT_NE(reference.find("modal"), std::string::npos) << reference;  // the reasoning's cheaper models ran
  EXPECT_NE(reference.find("nodal N=32"), std::string::npos) << reference;  // and the converged one on the verified cell
  for (const char* file : {"report.md", "operability.png", "summary.json", "operability.gp", "journal.tsv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "serial" / file)) << file;
  }
  const RunOutput threads = run(0, dir / "threads", dir, {"--threads", "2"});
  ASSERT_EQ(threads.end.exit_code, 0) << threads.err;
  EXPECT_EQ(table_without_timing(dir / "threads/operability.csv"), reference);
  if (!mpirun_unavailable_reason().empty()) GTEST_SKIP() << mpirun_unavailable_reason();
  const RunOutput mpi = run(3, dir / "np3", dir);
  ASSERT_EQ(mpi.end.exit_code, 0) << mpi.err;
  EXPECT_NE(mpi.out.find("MPI, 3 processes"), std::string::npos) << mpi.out;
  EXPECT_EQ(table_without_timing(dir / "np3/operability.csv"), reference);
}

TEST(CliOperability, KilledMidWayTheRerunResumesToTheSameTable) {
  ScratchDirectory dir;
  const std::filesystem::path out = dir / "out";
  {
    ChildSpec spec = operability(0, out, {"--threads", "1"});
    spec.stdout_file = dir / "killed.out";
    spec.stderr_file = dir / "killed.err";
    ChildProcess child(spec);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (journaled_records(out / "journal.tsv") < 3 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    child.signal_group(SIGKILL);
    ASSERT_TRUE(child.wait(std::chrono::seconds(30)));
  }
  const std::size_t journaled = journaled_records(out / "journal.tsv");
  ASSERT_GE(journaled, 3u);
  ASSERT_LT(journaled, 14u) << "the run finished before it could be killed";
  EXPECT_FALSE(std::filesystem::exists(out / "report.md")) << "a table was written before every record was done";
  EXPECT_FALSE(std::filesystem::exists(out / "operability.csv"));
  const RunOutput rerun = run(0, out, dir, {"--threads", "1"});
  ASSERT_EQ(rerun.end.exit_code, 0) << rerun.err;
  // A torn last line (the kill during a write) is computed again: at most one more than the difference.
  const std::size_t computed = 14 - journaled;
  EXPECT_TRUE(rerun.out.find(std::to_string(computed) + " records computed, " + std::to_string(journaled) + " resumed") !=
                  std::string::npos ||
              rerun.out.find(std::to_string(computed + 1) + " records computed, " + std::to_string(journaled - 1) + " resumed") !=
                  std::string::npos)
      << rerun.out;
  const RunOutput whole = run(0, dir / "whole", dir, {"--threads", "1"});
  ASSERT_EQ(whole.end.exit_code, 0) << whole.err;
  EXPECT_EQ(table_without_timing(out / "operability.csv"), table_without_timing(dir / "whole/operability.csv"));
}

// A 3 × 3 grid whose Hs = 3 m, Tp = 5 s cell is steeper than a sea can be (Hs ≤ λp/15 = 2.60 m at
// 5 s, 3.75 m at 6 s), with 20 components per record (they repeat within ~30 s at these periods).
TEST(CliOperability, ABreakingCellIsNotPhysicalAndARepeatingSeaIsWarnedAbout) {
  ScratchDirectory dir;
  ChildSpec spec;
  spec.argv = {ffrf, "operability", scene, "--hs", "1:3:3", "--tp", "5:7:3", "--seeds", "1", "--duration", "100",
               "--components", "20", "--verify", "0", "--threads", "2", "--cargo-motion-limit", "3",
               "--out", (dir / "out").string()};
  const RunOutput run = run_child(spec, dir.path(), std::chrono::minutes(10));
  // Exit 0: every physical cell has its verdict; the breaking cell is a result (not physical), not a failure.
  ASSERT_EQ(run.end.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("warning: the synthesized sea repeats within the 100-s record in 8 of 8 cells (20 wave "
                         "components each)"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("independent wave cycles"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("1 of 9 cells are steeper than a sea can be"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("estimated cost"), std::string::npos) << "the probe runs on a terminal only: " << run.err;
  EXPECT_NE(run.out.find("9 cells: "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("1 not physical (too steep to exist), 0 with a failed run"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("8 records computed"), std::string::npos) << run.out;
  const std::string csv = read_text(dir / "out/operability.csv");
  EXPECT_NE(csv.find("\n3,5,following,not_physical,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find(",failed,"), std::string::npos) << csv;
  const std::string report = read_text(dir / "out/report.md");
  EXPECT_NE(report.find("## Warnings"), std::string::npos);
  EXPECT_NE(report.find("not physical: Hs = 3 m at Tp = 5 s is steeper than a sea can be"), std::string::npos) << report;
  // The echoed command reproduces the run: the component count and every criterion are in it.
  EXPECT_NE(report.find("--seeds 1 --duration 100 --gamma 3.3 --components 20 --band-share 0.995 --tolerance 1% "
                        "--verify 0 --converged-elements 32 --daf-limit 0 --slack-margin 0.1 --cargo-motion-limit 3"),
            std::string::npos)
      << report;
  const std::string json = read_text(dir / "out/summary.json");
  EXPECT_NE(json.find("\"not_physical\""), std::string::npos);
  EXPECT_NE(json.find("repeats within the 100-s record"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/operability.png"));
  EXPECT_NE(read_text(dir / "out/operability.gp").find("not physical (too steep)"), std::string::npos);
}

TEST(CliOperability, AnAxisThatIsNotOneIsRefusedWithTheOptionNamed) {
  ScratchDirectory dir;
  ChildSpec spec;
  spec.argv = {ffrf, "operability", scene, "--hs", "3:1:2", "--tp", "8", "--out", (dir / "out").string()};
  const RunOutput bad = run_child(spec, dir.path(), std::chrono::minutes(1));
  EXPECT_EQ(bad.end.exit_code, 2);
  EXPECT_NE(bad.err.find("--hs 3:1:2"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out/report.md"));
}

}  // namespace
}  // namespace ffrf::test
