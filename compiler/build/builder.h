// CST -> AST: turns one parsed file (compiler/parse) into an ast::Module.
//
// The builder refuses formulas whose AST would be deeper than `kMaxFormulaDepth` (the
// pre-scan bounds brackets and prefix operators; long `=>` / `<=>` chains are bounded here),
// so every later recursive walk over the AST has a bounded depth.
#pragma once

#include "compiler/ast/ast.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/parse/parser.h"

namespace ksmc::compiler::build {

inline constexpr int kMaxFormulaDepth = 256;

// Builds the module of a successfully parsed file. `path` is recorded as Module::path.
ast::Module build_module(const parse::ParsedFile& parsed, const std::string& path, diag::DiagEngine& diags);

}  // namespace ksmc::compiler::build
