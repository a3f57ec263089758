#include "stdlib/indoor/io/type_style.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr Rgb kPalette[] = {{241, 194, 50}, {106, 168, 79}, {61, 133, 198}, {153, 153, 153},
                            {204, 65, 37},  {142, 124, 195}, {230, 145, 56}, {69, 129, 142}};
constexpr Rgb kUntyped{220, 220, 220};

}  // namespace

Rgb type_colour(const std::vector<std::string>& types, const std::string& type) {
  const auto it = std::find(types.begin(), types.end(), type);
  if (type.empty() || it == types.end()) return kUntyped;
  return kPalette[static_cast<std::size_t>(it - types.begin()) % std::size(kPalette)];
}

Rgb lighten(Rgb c, double amount) {
  const auto mix = [amount](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::lround(v + (255.0 - v) * std::clamp(amount, 0.0, 1.0)));
  };
  return {mix(c.r), mix(c.g), mix(c.b)};
}

std::string hex(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b); }

std::string type_letter(const std::vector<std::string>& types, const std::string& type) {
  if (type.empty() || std::find(types.begin(), types.end(), type) == types.end()) return "";
  std::size_t n = 1;
  for (; n < type.size(); ++n) {
    const bool shared = std::any_of(types.begin(), types.end(), [&](const std::string& t) {
      return t != type && t.compare(0, n, type, 0, n) == 0;
    });
    if (!shared) break;
  }
  std::string out = type.substr(0, n);
  out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
