// Typed error of the map loader: every bad input names the file (and the YAML line when known).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor::io {

// What went wrong, so callers and tests can tell the cases apart without parsing messages.
enum class MapErrorKind {
  Unreadable,     // missing file, permission denied, read error
  YamlSyntax,     // the YAML does not parse
  YamlMissingKey, // a required key (image, resolution) is absent
  YamlBadValue,   // a key has a value of the wrong type or out of range
  NotAnImage,     // bytes are neither PNG nor PGM
  Truncated,      // the image ends before its header says it should
  BadHeader,      // malformed PGM/PNG header
  TooSmall,       // fewer than kMinMapSide cells along a side
  TooLarge,       // more than kMaxMapCells cells (refused before decoding)
  NoFreeCells,    // the classified map has no free cell
  BadOption,      // a caller-supplied option is invalid (e.g. resolution <= 0)
};

const char* to_string(MapErrorKind kind);

class MapLoadError : public std::runtime_error {
 public:
  // `line` is 1-based; 0 means "no line" (image files, whole-document errors).
  MapLoadError(MapErrorKind kind, std::filesystem::path file, int line, const std::string& message);

  MapErrorKind kind() const { return kind_; }
  const std::filesystem::path& file() const { return file_; }
  int line() const { return line_; }

 private:
  MapErrorKind kind_;
  std::filesystem::path file_;
  int line_;
};

}  // namespace ksmc::stdlib::indoor::io
