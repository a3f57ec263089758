// Test helpers: compile a source snippet (includes resolve against the repo's stdlib) and
// collect the diagnostics as "line:col: message" strings.
#pragma once

#include <string>
#include <vector>

#include "compiler/ast/ast.h"

namespace ksmc::tests::frontend {

struct Outcome {
  bool loaded = false;
  std::vector<std::string> errors;    // "line:col: message" (main file; other files get their path)
  std::vector<std::string> warnings;
  std::string rendered;               // what ksmc would print on stderr
  compiler::ast::Program program;
};

// Loads `text` as if it were a file of the repo's tests/frontend folder and runs the symbol
// table pass plus the check passes named in `passes` (all passes when empty).
Outcome compile(const std::string& text, const std::vector<std::string>& passes = {});

// Parse + build only (no includes, no checks).
Outcome parse_only(const std::string& text);

bool contains(const std::vector<std::string>& msgs, const std::string& needle);

}  // namespace ksmc::tests::frontend
