// Whole-folder atomic outputs. The files of a run are written into a hidden staging
// folder beside the target (".<name>.staging-<pid>"); commit() swaps it into place with
// one rename (renameat2 RENAME_EXCHANGE where the file system has it) and then removes
// the previous folder. A crash, kill or full disk therefore leaves either the previous
// complete folder or the new complete one, never a mix, and no stale file of an earlier
// run survives. An uncommitted staging folder is removed by the destructor, and one left
// by a killed process is removed by the next run that writes to the same target.
//
// Safety: an existing target is replaced only when it is empty or holds a summary.json
// (an earlier ksmc output); anything else is refused, so `--out $HOME` cannot wipe a home.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ksmc::runtime::io {

class StagedDir {
 public:
  // Checks the target and creates the staging folder (and the target's parents).
  // Throws std::runtime_error naming the target on failure.
  explicit StagedDir(const std::filesystem::path& target, std::string_view marker_file = "summary.json");
  ~StagedDir();  // removes the staging folder unless committed
  StagedDir(const StagedDir&) = delete;
  StagedDir& operator=(const StagedDir&) = delete;

  const std::filesystem::path& staging() const noexcept { return staging_; }
  const std::filesystem::path& target() const noexcept { return target_; }
  bool committed() const noexcept { return committed_; }

  struct Entry {
    std::string path;  // relative to the folder, '/'-separated
    std::uint64_t bytes = 0;
    std::string sha256;
  };
  // Every regular file in the staging folder (recursively), sorted by path, except `skip`.
  std::vector<Entry> manifest(std::string_view skip = {}) const;

  // Flushes every file to disk and renames the staging folder into place. Throws naming
  // the target on failure (the previous folder is then intact).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace ksmc::runtime::io
