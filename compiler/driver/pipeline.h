// The compiler pipeline: the ONE place that lists the stages, in order.
//
//   parse, build          load the file and its includes (compiler/parse, compiler/build)
//   check:<pass>          the semantic passes of compiler/check, each a named object,
//                         including the kit-contract passes
//   lower:mln             rules -> runtime clause program (compiler/lower/lower_mln.h)
//   lower:domain          model, extract, prior, likelihood, output, kernel, schedule ->
//                         the typed domain IR (compiler/lower/lower_domain.h)
//   emit:factors          <domain>_factors.{h,cpp} from the clause program
//   emit:model            <domain>_model.{h,cpp}, <domain>_main.cpp from the domain IR
//
// `ksmc check` runs to the end of check, `ksmc infer` to lower:mln, `ksmc emit`, `build`
// and `kit` through emit. `ksmc --list-passes` prints stage_names().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/ast/ast.h"
#include "compiler/build/loader.h"
#include "compiler/check/pass.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/emit/emit_factors.h"
#include "compiler/lower/domain_ir.h"
#include "compiler/lower/mln_ir.h"

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

// How far run_pipeline goes.
enum class Goal {
  Check,     // parse, build, check
  LowerMln,  // + lower:mln (ksmc infer)
  Lower,     // + lower:domain (--dump-domain-ir)
  Emit,      // + emit:factors, emit:model (ksmc emit / build / kit)
};

struct PipelineResult {
  FrontendResult front;
  lower::MlnIr mln;
  lower::DomainIr domain;
  std::vector<emit::GeneratedFile> files;  // Goal::Emit: factors, then (with a kit) model and main
  bool ok = false;                         // every stage up to the goal succeeded
};

PipelineResult run_pipeline(const std::string& path, const build::LoadOptions& options, diag::SourceManager& sources,
                            diag::DiagEngine& diags, Goal goal, const std::string* text = nullptr);

// The one-line summary of a checked main module: "10 rules, 5 evidence, ...".
std::string summary(const ast::Module& main, const check::SymbolTable& symbols);

}  // namespace ksmc::compiler::driver
