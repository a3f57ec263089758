#include "runtime/cli/checked_flags.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "runtime/cli/domain_spec.h"

namespace ksmc::runtime::cli {

namespace fs = std::filesystem;

std::uint64_t parse_count(std::string_view flag, std::string_view text, std::uint64_t min, std::uint64_t max) {
  const auto refuse = [&](std::string_view why) {
    return UsageError(fmt::format("{}: expected a whole number from {} to {}, got '{}'{}", flag, min, max, text, why));
  };
  std::uint64_t v = 0;
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits) throw refuse(!text.empty() && text.front() == '-' ? " (negative)" : "");
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range) throw refuse(" (too large)");
  if (ec != std::errc() || p != text.data() + text.size()) throw refuse("");
  if (v < min || v > max) throw refuse("");
  return v;
}

double parse_amount(std::string_view flag, std::string_view text) {
  double v = 0.0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || p != text.data() + text.size() || !std::isfinite(v) || v < 0.0) {
    throw UsageError(fmt::format("{}: expected a number >= 0, got '{}'", flag, text));
  }
  return v;
}

void check_input_file(const fs::path& path, std::uint64_t max_bytes) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw std::runtime_error(fmt::format("{}: cannot open: no such file", path.string()));
  const char* kind = fs::is_directory(st)           ? "a folder"
                     : fs::is_character_file(st)     ? "a character device"
                     : fs::is_block_file(st)         ? "a block device"
                     : fs::is_fifo(st)               ? "a pipe"
                     : fs::is_socket(st)             ? "a socket"
                     : !fs::is_regular_file(st)      ? "not a regular file"
                                                     : nullptr;
  if (kind != nullptr) {
    throw std::runtime_error(fmt::format("{}: expected a regular file, this is {}", path.string(), kind));
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw std::runtime_error(fmt::format("{}: cannot read its size: {}", path.string(), ec.message()));
  if (size > max_bytes) {
    throw std::runtime_error(fmt::format("{}: {:.1f} MB exceeds the input size limit of {} MB (raise it with "
                                         "--max-input-mb)",
                                         path.string(), static_cast<double>(size) / 1e6, max_bytes / 1000000));
  }
}

}  // namespace ksmc::runtime::cli
