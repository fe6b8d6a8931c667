// The process's place in a distributed run, for the lifetime of the program: serial (no launcher:
// MPI is never touched) or one rank of an MPI job (the launcher started it: MPI is initialised
// with MPI_THREAD_FUNNELED, so that rank 0's main thread alone calls MPI while a worker thread of
// the same process computes). Create one Session in main (or in the command that farms tasks)
// before any farm and keep it until the end; it finalises MPI when destroyed. Without MPI in the
// build (FFRF_WITH_MPI=OFF) a program started by a launcher as several processes is refused:
// each process would otherwise compute and write everything.
#pragma once

#include <string>

#include "distributed/launch.hpp"

namespace ffrf::distributed {

class Session {
 public:
  Session();  // from this process's environment (launch.hpp); throws EngineError
  explicit Session(const LaunchInfo& launch);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }  // only the root writes outputs
  bool uses_mpi() const { return mpi_; }
  // MPI granted at least MPI_THREAD_FUNNELED (always true without MPI): rank 0 may compute on a
  // thread of its own while its main thread schedules.
  bool threads_beside_mpi() const { return funneled_; }
  const LaunchInfo& launch() const { return launch_; }
  // "serial (no launcher)" or "MPI, 3 processes (mpirun; Open MPI v4.1.4)".
  std::string description() const;

  // After an MPI call failed: the destructor aborts the job (MPI_Abort) instead of finalising,
  // which could wait forever for a lost rank.
  void mark_broken() { broken_ = true; }

  // Whether this build can run on several processes (FFRF_WITH_MPI).
  static bool mpi_built_in();

 private:
  LaunchInfo launch_;
  int rank_ = 0;
  int size_ = 1;
  bool mpi_ = false;
  bool funneled_ = true;
  bool broken_ = false;
  std::string library_;
};

}  // namespace ffrf::distributed
