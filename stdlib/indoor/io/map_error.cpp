#include "stdlib/indoor/io/map_error.h"

#include <utility>

namespace ksmc::stdlib::indoor::io {

const char* to_string(MapErrorKind kind) {
  switch (kind) {
    case MapErrorKind::Unreadable: return "unreadable";
    case MapErrorKind::YamlSyntax: return "yaml-syntax";
    case MapErrorKind::YamlMissingKey: return "yaml-missing-key";
    case MapErrorKind::YamlBadValue: return "yaml-bad-value";
    case MapErrorKind::NotAnImage: return "not-an-image";
    case MapErrorKind::Truncated: return "truncated";
    case MapErrorKind::BadHeader: return "bad-header";
    case MapErrorKind::TooSmall: return "too-small";
    case MapErrorKind::TooLarge: return "too-large";
    case MapErrorKind::NoFreeCells: return "no-free-cells";
    case MapErrorKind::BadOption: return "bad-option";
  }
  return "unknown";
}

namespace {

std::string format_message(const std::filesystem::path& file, int line, const std::string& message) {
  std::string out = file.string();
  if (line > 0) out += ":" + std::to_string(line);
  out += ": error: " + message;
  return out;
}

}  // namespace

MapLoadError::MapLoadError(MapErrorKind kind, std::filesystem::path file, int line,
                           const std::string& message)
    : std::runtime_error(format_message(file, line, message)),
      kind_(kind),
      file_(std::move(file)),
      line_(line) {}

}  // namespace ksmc::stdlib::indoor::io
