// Output that is complete or absent: files are written into a staging directory next to the
// target and moved into place by commit(), the completeness marker (summary.json) last. Creating
// a StagedDirectory removes the target's old marker (its files are about to be replaced); without
// commit() — an error, an exception — the staging directory is removed and no marker is left.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace ffrf::report {

class StagedDirectory {
 public:
  // Creates the staging directory and removes target/marker.
  StagedDirectory(std::filesystem::path target, std::string marker);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }
  // Writes a file into the staging directory; throws std::runtime_error on failure.
  void write(std::string_view name, std::string_view content) const;
  // Moves everything into the target (created if needed), the marker last.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::string marker_;
  bool committed_ = false;
};

}  // namespace ffrf::report
