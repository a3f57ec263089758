// FNV-1a 64-bit hashes of input files, recorded in summary.json so a result can be
// matched to the exact input it came from. (FNV-1a, not SHA-256: it identifies inputs,
// it is not meant to resist tampering.)
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ksmc::runtime::cli {

struct FileHash {
  std::filesystem::path path;
  std::uint64_t bytes = 0;
  std::uint64_t fnv1a64 = 0;
  std::string hex() const;  // 16 lowercase hex digits
};

inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;
inline constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

constexpr std::uint64_t fnv1a64(std::string_view data, std::uint64_t h = kFnvOffset) noexcept {
  for (const char c : data) {
    h ^= static_cast<unsigned char>(c);
    h *= kFnvPrime;
  }
  return h;
}

// Throws std::runtime_error naming the file when it cannot be read.
FileHash hash_file(const std::filesystem::path& path);

}  // namespace ksmc::runtime::cli
