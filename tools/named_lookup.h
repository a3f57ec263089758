// Lookup of a named entry in a fixed table (scene families of the test-scene generators),
// with an error that lists the known names, and the FNV-1a hash of a name (families draw
// disjoint scene seeds from it). Header-only; tools only.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace ksmc::tools {

// The entry whose `name` member equals `name`; throws std::invalid_argument
// "unknown <what> '<name>' (known: a, b, ...)".
template <typename T>
const T& find_named(std::span<const T> table, std::string_view name, std::string_view what) {
  std::string known;
  for (const auto& entry : table) {
    if (entry.name == name) return entry;
    known += (known.empty() ? "" : ", ") + std::string(entry.name);
  }
  throw std::invalid_argument(fmt::format("unknown {} '{}' (known: {})", what, name, known));
}

inline std::uint64_t name_hash(std::string_view name) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

}  // namespace ksmc::tools
