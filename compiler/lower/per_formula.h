// Per-formula weight semantics (`--per-formula` of ksmc infer / learn / import-mln).
//
// By default a soft formula of weight w whose CNF has k clauses contributes k clauses of
// weight w / k (as Alchemy does): a world gains w / k per satisfied clause. Under
// per-formula semantics (Richardson & Domingos) it gains w once when the whole formula
// holds. This rewrite gives every such formula F(v) (v: its universal variables) an
// auxiliary query predicate holds[F](v) that the hard rules make equivalent to F,
//   hard !holds[F](v) v C_i(v)                 for each CNF clause C_i = l_i1 v ... v l_in
//   hard holds[F](v) v !l_1j1 v ... v !l_kjk   for each choice of one literal per clause
// (together: F => holds[F], as !F = !C_1 v ... v !C_k), and one soft clause holds[F](v) of
// weight w. holds[F] is a function of the other atoms, so marginals and log Z are those
// of the per-formula MLN exactly. The auxiliary predicates are marked
// Predicate::auxiliary (outputs skip them). Formulas of one clause are unchanged.
//
// Refused (an error naming the rule): a multi-clause formula with `exists` (its negation
// would need universal clauses of its own), or one whose literal choices exceed 256
// clauses.
#pragma once

#include <string>

#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::lower {

// Rewrites `ir` in place; returns an empty string, or the error ("file:line: error: ...").
// Afterwards each rewritten RuleIr lists only its soft clause (scale 1 for learning).
std::string use_per_formula_weights(MlnIr& ir);

}  // namespace ksmc::compiler::lower
