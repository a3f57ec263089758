// The front-end pipeline: the ONE place that lists the passes, in order.
//
//   load   = parse (compiler/parse) + build (compiler/build) of the file and its includes
//   check  = the semantic passes of compiler/check, each a named object
//
// Later stages (lower, emit) append here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/build/loader.h"
#include "compiler/check/pass.h"
#include "compiler/diag/diagnostics.h"

namespace ksmc::compiler::driver {

// The check passes in execution order.
std::vector<std::unique_ptr<check::Pass>> make_check_passes();
// Names of every pipeline stage and pass, in order (for `ksmc --list-passes`).
std::vector<std::string> pass_names();

struct FrontendResult {
  ast::Program program;
  check::SymbolTable symbols;
  bool loaded = false;  // parse + build succeeded for every file
  bool ok = false;      // and no check reported an error
};

// Loads and checks `path` (or `text` when given). Diagnostics go to `diags`.
FrontendResult run_frontend(const std::string& path, const build::LoadOptions& options, diag::SourceManager& sources,
                            diag::DiagEngine& diags, const std::string* text = nullptr);

// Runs the check passes over an already loaded program.
bool run_checks(const ast::Program& program, diag::DiagEngine& diags, check::SymbolTable& symbols);

// The one-line summary of a checked main module: "10 rules, 5 evidence, ...".
std::string summary(const ast::Module& main, const check::SymbolTable& symbols);

}  // namespace ksmc::compiler::driver
