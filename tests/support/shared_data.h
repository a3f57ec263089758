// Locating ../shared test data; tests skip (with a message) when it is absent.
#pragma once

#include <filesystem>
#include <iostream>
#include <string>

namespace ksmc::tests {

inline std::filesystem::path shared_dir() { return std::filesystem::path(KSMC_SHARED_DIR); }

// Returns true when `rel` exists under the shared folder; otherwise prints why the
// caller is skipping and returns false.
inline bool have_shared(const std::string& rel) {
  const auto p = shared_dir() / rel;
  if (std::filesystem::exists(p)) return true;
  std::cout << "SKIP: " << p.string() << " not found (../shared absent)\n";
  return false;
}

}  // namespace ksmc::tests
