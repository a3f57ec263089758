// Command-line reading shared by the scene generator tools (ksmc-scenegen,
// ksmc-scenegen-families): `--flag value` pairs, valueless switches, --help / -h, whole
// numbers checked to the last character. Errors are UsageError (the tools exit 2).
#pragma once

#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

namespace ksmc::tools::tabletop_sim {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "--seed", "x1" -> UsageError "--seed: 'x1' is not a valid number".
template <typename T>
T parse_number(std::string_view flag, std::string_view text) {
  T value{};
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) {
    throw UsageError(fmt::format("{}: '{}' is not a valid number", flag, text));
  }
  return value;
}

// What a tool does with a flag before it is read as `--flag value`.
enum class Switch {
  no,     // not a switch: the next argument is its value
  taken,  // a switch without a value, handled
  stop,   // handled, and the tool is done (exit 0), e.g. after printing a list
};

// Reads argv[1..]: --help / -h prints `usage` on stdout and stops; otherwise `on_switch(flag)`
// says whether the flag is a switch, and `on_value(flag, value)` takes the value of any other
// flag (false: unknown flag). Returns false when the tool should stop (exit 0). Throws
// UsageError for a flag without its value or an unknown flag.
template <typename OnSwitch, typename OnValue>
bool read_flags(int argc, char** argv, const char* usage, OnSwitch on_switch, OnValue on_value) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view flag = args[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(usage, stdout);
      return false;
    }
    const Switch s = on_switch(flag);
    if (s == Switch::stop) return false;
    if (s == Switch::taken) continue;
    if (i + 1 >= args.size()) throw UsageError(fmt::format("{}: missing value", flag));
    const std::string_view value = args[++i];
    if (!on_value(flag, value)) throw UsageError(fmt::format("unknown option '{}'", flag));
  }
  return true;
}

}  // namespace ksmc::tools::tabletop_sim
