// The engine built without MPI (FFRF_WITH_MPI=OFF): a session is always a single process
// (session.cpp refuses a launcher's several processes), so there are no other ranks to reach.
#include "distributed/errors.hpp"
#include "distributed/rank_transport.hpp"

namespace ffrf::distributed {

std::unique_ptr<RankTransport> connect_ranks(Session&, const Handshake&) { return nullptr; }

void serve_tasks(Session& session, const Handshake&, const std::vector<Task>&, const WorkFunction&) {
  throw EngineError("rank " + std::to_string(session.rank()) + " of a build without MPI: nothing to serve");
}

}  // namespace ffrf::distributed
