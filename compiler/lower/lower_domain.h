// Lowering of the sampler half of a checked domain to the typed domain IR (domain_ir.h).
// Runs after `ksmc check` accepted the file: calls resolve, arguments fit their parameters.
#pragma once

#include <string>

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"
#include "compiler/diag/source_manager.h"
#include "compiler/lower/domain_ir.h"

namespace ksmc::compiler::lower {

DomainIr lower_domain(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources);

// The stdlib package that declares the domain's likelihood: "stdlib/indoor.ksm" gives
// "indoor". Empty when the domain has no likelihood or it is not declared in stdlib/.
std::string kit_of(const ast::Program& program, const check::SymbolTable& symbols);

}  // namespace ksmc::compiler::lower
