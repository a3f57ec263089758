// Atomic output files: write to a temporary sibling, then rename over the target,
// so a reader never sees a half-written file, even after an error or Ctrl-C.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>

namespace ksmc::runtime::io {

// Writes `data` to `path` atomically. Throws std::runtime_error naming the path on failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view data);
void write_file_atomic(const std::filesystem::path& path, std::span<const unsigned char> data);

// Replaces the contents of an existing file atomically, in place: a symbolic link is
// followed (the link stays a link; its target gets the new contents) and the file's
// permission bits are kept (ksmc fmt --in-place).
void rewrite_file_atomic(const std::filesystem::path& path, std::string_view data);

}  // namespace ksmc::runtime::io
