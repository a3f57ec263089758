// `ksmc emit`, second half: the sampler glue of a domain.
//
//   <domain>_model.h/.cpp  domain_config(): every model, extract, prior, likelihood, kernel
//                          and schedule item of the domain file as a
//                          ksmc::runtime::domain::DomainConfig (stdlib calls with parameters
//                          checked against their declared signatures, defaults filled in,
//                          numbers in base units), one statement per item with the item's
//                          text and file:line; mln_binding(): the generated factors.
//   <domain>_main.cpp      the entry point: the common domain CLI over the domain's stdlib
//                          kit, configured by domain_config().
//
// One schedule row, one extractor, one kernel declaration: one line each, so editing one
// probability or parameter in the domain file changes one line of the output.
#pragma once

#include <string>

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"
#include "compiler/diag/source_manager.h"
#include "compiler/emit/emit_factors.h"

namespace ksmc::compiler::emit {

struct ModelOutput {
  GeneratedFile header;
  GeneratedFile source;
  GeneratedFile main;
};

// `kit`: the stdlib package whose kit runs the domain (e.g. "tabletop"): the package of the
// file declaring the domain's likelihood (see kit_of()).
ModelOutput emit_model(const ast::Program& program, const check::SymbolTable& symbols,
                       const diag::SourceManager& sources, const std::string& kit);

// The stdlib package that declares the domain's likelihood: "stdlib/indoor.ksm" gives
// "indoor". Empty when the domain has no likelihood or it is not declared in stdlib/.
std::string kit_of(const ast::Program& program, const check::SymbolTable& symbols,
                   const diag::SourceManager& sources);

}  // namespace ksmc::compiler::emit
