// Temporary file, fsync, rename (see atomic_file.hpp).
#include "distributed/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace ffrf::distributed {

void write_file_atomically(const std::filesystem::path& target, std::string_view content) {
  const std::filesystem::path directory = target.parent_path().empty() ? "." : target.parent_path();
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw std::runtime_error(fmt::format("{}: cannot create the directory: {}", directory.string(), error.message()));
  const std::filesystem::path temporary =
      directory / fmt::format(".{}.tmp-{}", target.filename().string(), static_cast<long>(::getpid()));
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(fmt::format("{}: cannot be created: {}", temporary.string(), std::strerror(errno)));
  std::size_t written = 0;
  bool ok = true;
  while (ok && written < content.size()) {
    const ssize_t count = ::write(fd, content.data() + written, content.size() - written);
    if (count < 0 && errno == EINTR) continue;
    ok = count >= 0;
    if (ok) written += static_cast<std::size_t>(count);
  }
  ok = ok && ::fsync(fd) == 0;
  const std::string reason = ok ? std::string() : std::strerror(errno);
  ::close(fd);
  if (!ok || ::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string why = ok ? std::strerror(errno) : reason;
    ::unlink(temporary.c_str());
    throw std::runtime_error(fmt::format("{}: cannot be written: {}", target.string(), why));
  }
}

}  // namespace ffrf::distributed
