// SHA-256 (FIPS 180-4) of byte strings and files, for the output manifest in summary.json.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ksmc::runtime::io {

class Sha256 {
 public:
  Sha256() noexcept;
  void update(const void* data, std::size_t size) noexcept;
  void update(std::string_view data) noexcept { update(data.data(), data.size()); }
  std::array<std::uint8_t, 32> finish() noexcept;  // call once
  std::string hex() noexcept;                      // finish() as 64 lowercase hex digits

 private:
  void block(const std::uint8_t* p) noexcept;
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buf_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;  // bytes
};

std::string sha256_hex(std::string_view data);

struct FileDigest {
  std::uint64_t bytes = 0;
  std::string sha256;  // hex
};
// Throws std::runtime_error naming the file when it cannot be read.
FileDigest sha256_file(const std::filesystem::path& path);

}  // namespace ksmc::runtime::io
