// Bounded grounding, said up front (issue 16): before a program is grounded, the number of
// ground clauses of every rule after evidence folding is estimated, and a rule above the
// limit is refused with an MlnError naming the rule, its binding and the estimate, instead
// of grounding for minutes or running out of memory.
//
// The estimate of a rule is the product of the domain sizes of its universal variables
// (existential ones make literals, not clauses), refined by its closed-world evidence
// literals: a grounding survives folding only where such a literal is false, so a literal
// `!e(x, y)` bounds the rule by (true atoms of e) x (sizes of the variables not in it),
// and `e(x, y)` by the false atoms. The smallest of these bounds is taken. It is an upper
// bound: groundings satisfied by other evidence are still counted.
#pragma once

#include <cstdint>
#include <string>

#include "runtime/mln/error.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace ksmc::runtime::mln {

// The refusal: a bad input (exit 1), never "this state is impossible" (which other
// MlnErrors of grounding, like an unsatisfiable hard rule, mean to a kit's semantics).
class GroundingTooLarge : public MlnError {
 public:
  using MlnError::MlnError;
};

inline constexpr std::uint64_t kDefaultMaxGroundClauses = 50'000'000;

// The limit checked by check_ground_bound (process-wide; set by --max-ground-clauses).
// 0 means no limit.
void set_max_ground_clauses(std::uint64_t limit) noexcept;
std::uint64_t max_ground_clauses() noexcept;

struct GroundEstimate {
  double bindings = 1.0;    // product of the universal variables' domain sizes
  double clauses = 1.0;     // after evidence folding (upper bound)
  std::string binding;      // "x1:node(8) x x2:node(8) ..." (universal variables)
};

GroundEstimate estimate_ground_clauses(const Program& program, const Domain& domain, const Evidence& evidence,
                                       const Clause& clause);

// Throws GroundingTooLarge for the first rule whose estimate exceeds max_ground_clauses(), and for
// a program whose rules together exceed it.
void check_ground_bound(const Program& program, const Domain& domain, const Evidence& evidence);

}  // namespace ksmc::runtime::mln
