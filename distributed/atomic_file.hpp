// A file that is complete or absent: the content is written to a temporary file beside the
// target, flushed to disk and renamed over the target (rename is atomic within a file system), so
// a reader or a killed run never sees half a table.
#pragma once

#include <filesystem>
#include <string_view>

namespace ffrf::distributed {

// Throws std::runtime_error naming the file and the system's reason.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace ffrf::distributed
