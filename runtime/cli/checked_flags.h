// Checks of the common flags and inputs before any work starts (exit 2 / exit 1):
// counts are whole numbers in range (no "-5" wrapping to 2^64 - 5, no silent overflow),
// inputs are regular files under a size limit (no directory read as an empty file, no
// /dev/zero read until memory runs out).
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string_view>

namespace ksmc::runtime::cli {

inline constexpr std::uint64_t kCountMax = std::numeric_limits<std::uint64_t>::max();

// "--iterations", "-5", 1, kCountMax -> throws UsageError
// "--iterations: expected a whole number from 1 to 18446744073709551615, got '-5'".
std::uint64_t parse_count(std::string_view flag, std::string_view text, std::uint64_t min = 0,
                          std::uint64_t max = kCountMax);

// "--plateau-gain", "abc" -> throws UsageError
// "--plateau-gain: expected a number >= 0, got 'abc'" (also for nan, inf and negatives).
double parse_amount(std::string_view flag, std::string_view text);

// Default of --max-input-mb: the largest input file read without the flag.
inline constexpr std::uint64_t kDefaultMaxInputMb = 2048;

// Throws std::runtime_error naming the file: missing, not a regular file (folder, device,
// pipe), or larger than max_bytes (the message names --max-input-mb).
void check_input_file(const std::filesystem::path& path, std::uint64_t max_bytes);

}  // namespace ksmc::runtime::cli
