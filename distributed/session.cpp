// MPI initialisation and finalisation, or none (see session.hpp).
#include "distributed/session.hpp"

#include <fmt/format.h>

#include <atomic>

#include "distributed/errors.hpp"

#if FFRF_WITH_MPI
#include <mpi.h>
#endif

namespace ffrf::distributed {
#if FFRF_WITH_MPI
namespace {
std::atomic<bool> mpi_session_exists{false};  // MPI can be initialised once per process
}
#endif

Session::Session() : Session(detect_launch()) {}

Session::Session(const LaunchInfo& launch) : launch_(launch) {
  if (!launch_.launched) return;
#if FFRF_WITH_MPI
  if (mpi_session_exists.exchange(true)) {
    throw EngineError("a second distributed::Session in one process: MPI is initialised once; keep one Session for the program");
  }
  int provided = MPI_THREAD_SINGLE;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    throw EngineError(fmt::format("MPI_Init_thread failed (started by {} as rank {})", launch_.launcher, launch_.rank));
  }
  mpi_ = true;
  funneled_ = provided >= MPI_THREAD_FUNNELED;
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);  // failures become EngineErrors, named
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(version, &length);
  library_.assign(version, static_cast<std::size_t>(length));
  library_ = library_.substr(0, library_.find(','));  // "Open MPI v4.1.4, package: ..." -> "Open MPI v4.1.4"
#else
  if (launch_.size > 1) {
    throw EngineError(fmt::format(
        "started by {} as one of {} processes, but this build has no MPI (FFRF_WITH_MPI=OFF): every process would "
        "compute and write everything; run the program without a launcher, or rebuild with MPI (libopenmpi-dev)",
        launch_.launcher, launch_.size));
  }
#endif
}

Session::~Session() {
#if FFRF_WITH_MPI
  if (!mpi_) return;
  if (broken_) {
    MPI_Abort(MPI_COMM_WORLD, 1);
  } else {
    MPI_Finalize();
  }
  mpi_session_exists = false;
#endif
}

std::string Session::description() const {
  if (!mpi_) {
    return launch_.launched ? fmt::format("serial (started by {} as a single process; no MPI)", launch_.launcher)
                            : std::string("serial (no launcher)");
  }
  return fmt::format("MPI, {} process{} ({}; {})", size_, size_ == 1 ? "" : "es", launch_.launcher, library_);
}

bool Session::mpi_built_in() {
#if FFRF_WITH_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace ffrf::distributed
