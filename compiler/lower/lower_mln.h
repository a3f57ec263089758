// Lowering of the checked AST's Markov logic part (types, predicates, rules) to the
// runtime's first-order clause program (runtime/mln/program.h).
//
//  * `prob p: F` gets weight log(p / (1 - p)); `w x: F` gets x; `hard F` is hard.
//  * F is converted to clauses (compiler/lower/cnf.h); a soft formula that becomes k
//    clauses gives each clause weight w / k (Alchemy's convention).
//  * `exactly one of P1(x), ..., Pk(x)` becomes an exactly-one group, and Alchemy's
//    `p(x, t!)` an exclusive argument: both are constraints the engines respect
//    structurally, not clauses.
//  * Existential variables stay in their clause and are expanded over the domain at
//    grounding time.
#pragma once

#include "compiler/ast/ast.h"
#include "compiler/check/symbols.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::lower {

// Runs on a program that passed the checks. Returns false (with diagnostics) when a rule
// cannot be lowered (an existential over a conjunction, a formula too large to expand).
bool lower_mln(const ast::Program& program, const check::SymbolTable& symbols,
               const diag::SourceManager& sources, diag::DiagEngine& diags, MlnIr& out);

}  // namespace ksmc::compiler::lower
