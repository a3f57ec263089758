// Loads a program: the main file and, transitively, every file it includes (each once),
// running parse + build on each. Include paths are searched in the including file's folder
// and its ancestors, then in `include_dirs`; the path is recorded (and printed in
// diagnostics) relative the way it was found, so output does not depend on the machine.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/diag/diagnostics.h"

namespace ksmc::compiler::build {

struct LoadOptions {
  std::vector<std::string> include_dirs;
  bool follow_includes = true;  // false: only the main file (fmt, --dump-ast)
};

// Loads `path` from disk. Returns false when a file could not be read, parsed or built.
bool load_program(const std::string& path, const LoadOptions& options, diag::SourceManager& sources,
                  diag::DiagEngine& diags, ast::Program& out);

// Same, with the main file's text given (fuzzing, tests); `path` names it in diagnostics
// and anchors include search.
bool load_program_text(const std::string& path, std::string text, const LoadOptions& options,
                       diag::SourceManager& sources, diag::DiagEngine& diags, ast::Program& out);

// Reads a whole file (at most kMaxSourceBytes) and normalizes it (normalize_source); false
// (and `error` set) when it cannot be read or is not text.
inline constexpr std::size_t kMaxSourceBytes = 64'000'000;
bool read_file(const std::string& path, std::string& text, std::string& error);

// Drops a UTF-8 byte order mark and turns lone \r line ends into \n; false (and `error`
// naming line and column) for a NUL byte.
bool normalize_source(std::string& text, std::string& error);

}  // namespace ksmc::compiler::build
