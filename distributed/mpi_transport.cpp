// The MPI side of the engine (see rank_transport.hpp): point-to-point messages on MPI_COMM_WORLD,
// polled with MPI_Iprobe and short sleeps rather than blocking receives, which in Open MPI spin a
// core at 100 % while waiting: on a machine with as many processes as cores, an idle rank would
// otherwise slow down the ranks that compute. Compiled only with FFRF_WITH_MPI.
#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <thread>

#include "distributed/errors.hpp"
#include "distributed/rank_transport.hpp"

namespace ffrf::distributed {
namespace {

enum Tag : int { tag_hello = 1, tag_task = 2, tag_outcome = 3, tag_stop = 4 };
constexpr std::uint64_t protocol_version = 1;
using HelloMessage = std::array<std::uint64_t, 5>;

HelloMessage hello_message(const Handshake& handshake) {
  return {protocol_version, handshake.settings_hash, handshake.task_list_hash, handshake.shard.index, handshake.shard.count};
}

// Throws EngineError naming the call and the peer, and marks the session broken (MPI_Abort at exit).
void check(int code, const char* call, int peer, Session& session) {
  if (code == MPI_SUCCESS) return;
  session.mark_broken();
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw EngineError(fmt::format("MPI failure on rank {}: {} with {} failed: {} (a rank lost? the journal keeps every "
                                "finished task; rerun to resume)",
                                session.rank(), call, peer < 0 ? std::string("any rank") : fmt::format("rank {}", peer),
                                std::string(text, static_cast<std::size_t>(length))));
}

// Sleeps that grow from 20 µs to 1 ms while nothing arrives: quick answers, an idle core.
class Backoff {
 public:
  void wait() {
    std::this_thread::sleep_for(delay_);
    delay_ = std::min(delay_ * 2, std::chrono::microseconds(1000));
  }
  void reset() { delay_ = std::chrono::microseconds(20); }

 private:
  std::chrono::microseconds delay_{20};
};

// Waits (polling) for a message from `source` with `tag` (MPI_ANY_SOURCE, MPI_ANY_TAG allowed).
MPI_Status wait_for_message(int source, int tag, Session& session) {
  Backoff backoff;
  while (true) {
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe", source, session);
    if (flag) return status;
    backoff.wait();
  }
}

std::uint64_t receive_number(const MPI_Status& status, Session& session) {
  std::uint64_t value = 0;
  check(MPI_Recv(&value, 1, MPI_UINT64_T, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv", status.MPI_SOURCE, session);
  return value;
}

void send_number(std::uint64_t value, int rank, Tag tag, Session& session) {
  check(MPI_Send(&value, 1, MPI_UINT64_T, rank, tag, MPI_COMM_WORLD), "MPI_Send", rank, session);
}

class MpiTransport final : public RankTransport {
 public:
  explicit MpiTransport(Session& session)
      : session_(session), busy_(static_cast<std::size_t>(session.size()), false), task_of_(busy_.size(), 0) {}

  std::size_t ranks() const override { return busy_.size() - 1; }
  std::size_t busy() const override { return busy_count_; }
  std::optional<int> idle_rank() const override {
    for (std::size_t rank = 1; rank < busy_.size(); ++rank) {
      if (!busy_[rank]) return static_cast<int>(rank);
    }
    return std::nullopt;
  }
  void send_task(int rank, std::size_t position) override {
    send_number(position, rank, tag_task, session_);
    busy_[static_cast<std::size_t>(rank)] = true;
    task_of_[static_cast<std::size_t>(rank)] = position;
    ++busy_count_;
  }
  std::optional<TaskOutcome> poll() override {
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, tag_outcome, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe", -1, session_);
    if (!flag) return std::nullopt;
    int length = 0;
    check(MPI_Get_count(&status, MPI_CHAR, &length), "MPI_Get_count", status.MPI_SOURCE, session_);
    std::string text(static_cast<std::size_t>(length), '\0');
    check(MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, tag_outcome, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv", status.MPI_SOURCE, session_);
    std::optional<TaskOutcome> outcome = decode_outcome(text);
    if (!outcome) {
      session_.mark_broken();
      throw EngineError(fmt::format("rank {} sent an outcome rank 0 cannot read ({} bytes)", status.MPI_SOURCE, length));
    }
    const auto rank = static_cast<std::size_t>(status.MPI_SOURCE);
    if (rank >= busy_.size() || !busy_[rank] || outcome->index != task_of_[rank]) {
      session_.mark_broken();
      throw EngineError(fmt::format("rank {} sent the outcome of task {}, which it was not given", rank, outcome->index));
    }
    busy_[rank] = false;
    --busy_count_;
    return outcome;
  }
  void release() override {
    Backoff backoff;
    while (busy_count_ > 0) {  // a busy rank finishes its task and sends it before it reads a stop
      if (poll()) {
        backoff.reset();
      } else {
        backoff.wait();
      }
    }
    for (std::size_t rank = 1; rank < busy_.size(); ++rank) send_number(0, static_cast<int>(rank), tag_stop, session_);
  }

 private:
  Session& session_;
  std::vector<bool> busy_;
  std::vector<std::size_t> task_of_;  // the position each busy rank is computing
  std::size_t busy_count_ = 0;
};

}  // namespace

std::unique_ptr<RankTransport> connect_ranks(Session& session, const Handshake& handshake) {
  if (session.size() <= 1) return nullptr;
  auto transport = std::make_unique<MpiTransport>(session);
  const HelloMessage expected = hello_message(handshake);
  std::optional<std::string> disagreement;
  for (int answered = 1; answered < session.size(); ++answered) {
    const MPI_Status status = wait_for_message(MPI_ANY_SOURCE, tag_hello, session);
    HelloMessage hello{};
    check(MPI_Recv(hello.data(), static_cast<int>(hello.size()), MPI_UINT64_T, status.MPI_SOURCE, tag_hello,
                   MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv", status.MPI_SOURCE, session);
    if (hello != expected && !disagreement) {
      disagreement = fmt::format(
          "rank {} built another farm than rank 0 (protocol {}, settings {:016x}, task list {:016x}, shard {}/{}; rank 0: "
          "protocol {}, settings {:016x}, task list {:016x}, shard {}/{}): every rank must build the same tasks from the "
          "same inputs",
          status.MPI_SOURCE, hello[0], hello[1], hello[2], hello[3], hello[4], expected[0], expected[1], expected[2],
          expected[3], expected[4]);
    }
  }
  if (disagreement) {
    transport->release();
    throw EngineError(*disagreement);
  }
  return transport;
}

void serve_tasks(Session& session, const Handshake& handshake, const std::vector<Task>& tasks, const WorkFunction& work) {
  const HelloMessage hello = hello_message(handshake);
  check(MPI_Send(hello.data(), static_cast<int>(hello.size()), MPI_UINT64_T, 0, tag_hello, MPI_COMM_WORLD), "MPI_Send",
        0, session);
  while (true) {
    const MPI_Status status = wait_for_message(0, MPI_ANY_TAG, session);
    const std::uint64_t value = receive_number(status, session);
    if (status.MPI_TAG == tag_stop) return;
    if (status.MPI_TAG != tag_task || value >= tasks.size()) {
      session.mark_broken();
      throw EngineError(fmt::format("rank {} received a message it cannot read from rank 0 (tag {}, value {})",
                                    session.rank(), status.MPI_TAG, value));
    }
    const std::string text = encode_outcome(run_task(tasks[value], work, session.rank()));
    check(MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag_outcome, MPI_COMM_WORLD), "MPI_Send", 0,
          session);
  }
}

}  // namespace ffrf::distributed
