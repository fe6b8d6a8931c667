// Appending to a journal with POSIX calls: open, flock, read back, ftruncate, write, fsync (see
// journal.hpp).
#include "distributed/journal.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "distributed/errors.hpp"

namespace ffrf::distributed {
namespace {

std::string system_reason() { return std::strerror(errno); }

std::string read_all(int fd, const std::filesystem::path& file) {
  std::string text;
  char buffer[1 << 16];
  while (true) {
    const ssize_t count = ::read(fd, buffer, sizeof buffer);
    if (count == 0) break;
    if (count < 0) {
      if (errno == EINTR) continue;
      throw JournalError(fmt::format("{}: cannot be read: {}", file.string(), system_reason()));
    }
    text.append(buffer, static_cast<std::size_t>(count));
  }
  return text;
}

// Makes the directory entry of a new file durable too.
void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

Journal::Journal(std::filesystem::path file, const JournalHeader& header) : file_(std::move(file)) {
  const std::filesystem::path directory = file_.parent_path().empty() ? "." : file_.parent_path();
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw JournalError(fmt::format("{}: cannot create the directory: {}", directory.string(), error.message()));
  fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw JournalError(fmt::format("{}: cannot be opened: {}", file_.string(), system_reason()));
  try {
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
      throw JournalError(fmt::format("{}: in use by another run (it holds the lock): wait for it to end, or give this "
                                     "run another output directory",
                                     file_.string()));
    }  // a file system without locks (ENOLCK, EOPNOTSUPP) is used unlocked
    const std::string text = read_all(fd_, file_);
    std::optional<JournalContents> contents = parse_journal(text, file_.string());
    std::size_t keep = 0;
    if (contents) {
      if (const std::optional<std::string> why = header_mismatch(contents->header, header)) {
        throw JournalError(fmt::format(
            "{}: this journal cannot be resumed by this run: {}; it was made by \"{}\". Give this run another output "
            "directory, or move the journal away to start afresh",
            file_.string(), *why, contents->header.study));
      }
      previous_ = std::move(contents->outcomes);
      repaired_ = contents->torn_tail;
      keep = contents->intact_bytes;
    } else {
      repaired_ = !text.empty();  // a header cut short: nothing was journaled yet
    }
    if (keep != text.size() && ::ftruncate(fd_, static_cast<off_t>(keep)) != 0) {
      throw JournalError(fmt::format("{}: cannot cut off its torn last line: {}", file_.string(), system_reason()));
    }
    if (::lseek(fd_, static_cast<off_t>(keep), SEEK_SET) < 0) {
      throw JournalError(fmt::format("{}: cannot seek: {}", file_.string(), system_reason()));
    }
    if (!contents) {
      write_all(header_line(header));
      sync_directory(directory);
    }
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

void Journal::append(const TaskOutcome& outcome) { write_all(outcome_line(outcome)); }

void Journal::write_all(const std::string& bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t count = ::write(fd_, bytes.data() + written, bytes.size() - written);
    if (count < 0) {
      if (errno == EINTR) continue;
      throw JournalError(fmt::format("{}: cannot append: {}", file_.string(), system_reason()));
    }
    written += static_cast<std::size_t>(count);
  }
  if (::fsync(fd_) != 0) throw JournalError(fmt::format("{}: cannot flush to disk: {}", file_.string(), system_reason()));
}

}  // namespace ffrf::distributed
