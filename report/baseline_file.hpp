// The regression-baseline file: a JSON document, format "ffrf-baseline" version 2,
// that `ffrf baseline record` writes and `ffrf baseline check` reads (docs/baselines.md documents
// every field). It holds a study::Baseline (model, frequencies, statistics, histories) and where it
// came from: ffrf's version and git commit, the date, the scene file's path, name and content hash
// (FNV-1a 64-bit of its bytes: a cheap fingerprint that says whether the scene changed, not a
// security hash). Numbers are written in their shortest exact form, so a file read back gives the
// recorded doubles bit for bit.
#pragma once

#include <stdexcept>
#include <string>

#include "study/baseline.hpp"

namespace ffrf::report {

// Version 2 added the coupled crane's natural modes ("coupled_modes"); version 1 files (without
// them) are still read, with no coupled modes to check.
inline constexpr int baseline_format_version = 2;
inline constexpr int oldest_baseline_format_version = 1;

struct BaselineProvenance {
  std::string ffrf_version;
  std::string git_commit;  // "unknown" outside a git checkout; "-dirty" with uncommitted changes
  std::string date;        // ISO 8601, UTC
  std::string scene_path;  // as given on the command line
  std::string scene_name;
  std::string scene_hash;  // "fnv1a64:0123456789abcdef"
};

struct BaselineFile {
  BaselineProvenance provenance;
  study::Baseline baseline;
};

// A baseline file that cannot be used: the file, the key ("channels[2].min"), the value as written
// and what is wrong (with the valid range). what() is "FILE: KEY = VALUE: PROBLEM".
class BaselineFileError : public std::runtime_error {
 public:
  BaselineFileError(std::string file, std::string key, std::string value, std::string problem);
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, key_, value_, problem_;
};

// The provenance of a baseline recorded now from the scene file at `scene_path`.
BaselineProvenance baseline_provenance(const std::string& scene_path, const std::string& scene_name);
// "fnv1a64:..." of the file's bytes; throws BaselineFileError when it cannot be read.
std::string scene_file_hash(const std::string& path);
// The commit ffrf was built from ("unknown" when not built from a git checkout).
std::string git_commit();

// The document's text.
std::string baseline_json(const BaselineFile& file);
// Parses a document; `file` names it in errors. Throws BaselineFileError.
BaselineFile parse_baseline(const std::string& text, const std::string& file);
// Reads and parses the file at `path`. Throws BaselineFileError (also for a missing file).
BaselineFile read_baseline(const std::string& path);
// Writes `text` to `path` completely or not at all (a temporary file beside it, renamed); throws
// std::runtime_error naming the path and the system's reason.
void write_baseline(const std::string& path, const std::string& text);

}  // namespace ffrf::report
