// Staged output directory (see output_directory.hpp).
#include "report/output_directory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <mutex>
#include <system_error>
#include <utility>

#include "solve/stop_request.hpp"

namespace ffrf::report {

namespace fs = std::filesystem;

namespace {

// The staging directories not yet committed or removed, with the parents each created.
struct Uncommitted {
  fs::path staging;
  std::vector<fs::path> created_parents;
};
std::mutex registry_mutex;
std::vector<Uncommitted>& registry() {
  static std::vector<Uncommitted> entries;
  return entries;
}

void forget(const fs::path& staging) {
  const std::lock_guard lock(registry_mutex);
  auto& entries = registry();
  entries.erase(std::remove_if(entries.begin(), entries.end(), [&](const Uncommitted& e) { return e.staging == staging; }),
                entries.end());
}

void remove_quietly(const fs::path& staging, const std::vector<fs::path>& created_parents) noexcept {
  std::error_code ignored;
  if (!staging.empty()) fs::remove_all(staging, ignored);
  for (const fs::path& parent : created_parents) fs::remove(parent, ignored);  // only when empty
}

std::error_code last_error() { return {errno, std::generic_category()}; }

}  // namespace

StagedDirectory::StagedDirectory(fs::path target, std::string marker)
    : target_(std::move(target)), marker_(std::move(marker)) {
  if (target_.empty()) throw OutputError("output directory \"\": an empty path; give a directory name");
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
  std::error_code error;
  const fs::path parent = fs::absolute(target_, error).parent_path();
  if (error) fail("cannot resolve the path", error);
  // The missing parents, created one by one (and removed again when nothing is committed).
  std::vector<fs::path> missing;
  for (fs::path p = parent; !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, error) && error) {
      remove_quietly({}, created_parents_);
      fail(fmt::format("cannot create the directory {}", it->string()), error);
    }
    created_parents_.insert(created_parents_.begin(), *it);
  }
  if (fs::exists(target_, error) && !fs::is_directory(target_, error)) {
    remove_quietly({}, created_parents_);
    throw OutputError(fmt::format("output directory {}: exists and is not a directory", target_.string()));
  }
  if (fs::exists(target_, error) && !fs::remove(target_ / marker_, error) && error) {
    fail(fmt::format("cannot remove the old {}", marker_), error);
  }
  staging_ = parent / fmt::format(".{}.partial-{}", target_.filename().string(), ::getpid());
  fs::remove_all(staging_, error);
  if (!fs::create_directory(staging_, error)) {
    staging_.clear();
    remove_quietly({}, created_parents_);
    fail(fmt::format("cannot create files in {}", parent.string()), error ? error : std::make_error_code(std::errc::file_exists));
  }
  const std::lock_guard lock(registry_mutex);
  registry().push_back({staging_, created_parents_});
}

StagedDirectory::~StagedDirectory() {
  if (committed_ || staging_.empty()) return;
  forget(staging_);
  remove_quietly(staging_, created_parents_);
}

void StagedDirectory::fail(const std::string& what, const std::error_code& reason) const {
  throw OutputError(fmt::format("output directory {}: {}: {}", target_.string(), what, reason.message()));
}

void StagedDirectory::write(std::string_view name, std::string_view content) const {
  const fs::path path = staging_ / name;
  const std::string shown = (target_ / name).string();  // the user's path, not the staging one
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(fmt::format("cannot write {}", shown), last_error());
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::error_code reason = n < 0 ? last_error() : std::make_error_code(std::errc::no_space_on_device);
      ::close(fd);
      fail(fmt::format("cannot write {}", shown), reason);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(fmt::format("cannot write {}", shown), last_error());
}

void StagedDirectory::commit() {
  solve::throw_if_stop_requested();  // an interrupted run never poses as complete
  std::error_code error;
  if (!fs::exists(target_, error)) {
    fs::rename(staging_, target_, error);  // atomic: the whole directory appears at once
    if (error) fail("cannot move the results into place", error);
  } else {
    // The target exists (its old marker is gone): move file by file, the marker last.
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(staging_, error)) {
      if (entry.path().filename() != marker_) files.push_back(entry.path());
    }
    if (error) fail("cannot list the staged results", error);
    for (const fs::path& file : files) {
      fs::remove_all(target_ / file.filename(), error);
      if (!error) fs::rename(file, target_ / file.filename(), error);
      if (error) fail(fmt::format("cannot replace {}", (target_ / file.filename()).string()), error);
    }
    if (fs::exists(staging_ / marker_, error)) fs::rename(staging_ / marker_, target_ / marker_, error);
    if (error) fail(fmt::format("cannot write {}", (target_ / marker_).string()), error);
    fs::remove(staging_, error);
  }
  forget(staging_);
  committed_ = true;
}

void check_output_directory(const fs::path& target, const std::string& marker) {
  const StagedDirectory probe(target, marker);  // created and removed: the directory can be written
}

void remove_uncommitted_outputs() noexcept {
  const std::lock_guard lock(registry_mutex);
  for (const Uncommitted& entry : registry()) remove_quietly(entry.staging, entry.created_parents);
  registry().clear();
}

}  // namespace ffrf::report
