// Checks run on the raw bytes before ANTLR sees them, so that no input can crash or hang
// the parser: NUL bytes (binary files), invalid UTF-8, size, unterminated comments and
// strings, and nesting depth (ANTLR's recursive descent would exhaust the stack on
// megabytes of '(' — we refuse past `max_depth` with a located error).
#pragma once

#include <cstddef>
#include <string_view>

#include "compiler/diag/diagnostics.h"

namespace ksmc::compiler::parse {

struct PrescanLimits {
  std::size_t max_bytes = std::size_t{8} << 20;  // 8 MiB
  int max_depth = 256;  // brackets + prefix operators ('!', 'exists') in one statement
};

// Returns true when `text` may be handed to the parser; otherwise errors were reported.
bool prescan(int file, std::string_view text, diag::DiagEngine& diags, const PrescanLimits& limits = {});

}  // namespace ksmc::compiler::parse
