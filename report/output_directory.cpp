// Staged output directory (see output_directory.hpp).
#include "report/output_directory.hpp"

#include <fmt/format.h>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace ffrf::report {

namespace fs = std::filesystem;

StagedDirectory::StagedDirectory(fs::path target, std::string marker)
    : target_(std::move(target)), marker_(std::move(marker)) {
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
  const fs::path parent = fs::absolute(target_).parent_path();
  fs::create_directories(parent);
  if (fs::exists(target_) && !fs::is_directory(target_)) {
    throw std::runtime_error(fmt::format("--out {}: exists and is not a directory", target_.string()));
  }
  if (fs::exists(target_)) fs::remove(target_ / marker_);
  staging_ = parent / fmt::format(".{}.partial-{}", target_.filename().string(), ::getpid());
  fs::remove_all(staging_);
  fs::create_directory(staging_);
}

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagedDirectory::write(std::string_view name, std::string_view content) const {
  const fs::path path = staging_ / name;
  std::ofstream out(path, std::ios::binary);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

void StagedDirectory::commit() {
  if (!fs::exists(target_)) {
    fs::rename(staging_, target_);  // atomic: the whole directory appears at once
    committed_ = true;
    return;
  }
  // The target exists (its old marker is gone): move file by file, the marker last.
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    if (entry.path().filename() != marker_) files.push_back(entry.path());
  }
  for (const fs::path& file : files) {
    fs::remove_all(target_ / file.filename());
    fs::rename(file, target_ / file.filename());
  }
  if (fs::exists(staging_ / marker_)) fs::rename(staging_ / marker_, target_ / marker_);
  fs::remove(staging_);
  committed_ = true;
}

}  // namespace ffrf::report
