// A semantic check pass and the state the passes share. The pass list itself lives in ONE
// place: compiler/driver/pipeline.cpp.
#pragma once

#include <string>
#include <string_view>

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"
#include "compiler/diag/diagnostics.h"

namespace ksmc::compiler::check {

struct Context {
  const ast::Program& program;
  diag::DiagEngine& diags;
  SymbolTable symbols;

  // The main module (the file being checked); warnings are only given for its declarations.
  [[nodiscard]] const ast::Module& main() const { return program.modules.front(); }
  [[nodiscard]] std::string where(const ast::Loc& loc) const;  // "path:line:col"
};

class Pass {
 public:
  virtual ~Pass() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  virtual void run(Context& ctx) = 0;
  // Runs only when the passes before it found no error (its findings would be cascades).
  [[nodiscard]] virtual bool needs_clean_input() const { return false; }
};

// Formats a number for messages without trailing zeros ("0.95", "1000", "1e-12").
std::string format_number(double v);

// Closest candidate within a small edit distance, for "did you mean ...?" hints.
std::string suggest(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace ksmc::compiler::check
