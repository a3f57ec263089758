#include "runtime/mln/factor_context.h"

#include <string>

#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {

void FactorContext::hard(std::int32_t clause, std::initializer_list<std::int32_t> binding) {
  if (!lits_.empty()) {
    g_.network.add_hard_clause(lits_, clause);
    return;
  }
  const Clause& c = g_.program->clauses[static_cast<std::size_t>(clause)];
  std::string where;
  std::size_t v = 0;
  for (const std::int32_t value : binding) {
    const Variable& var = c.variables[v++];
    if (var.existential) continue;
    where += (where.empty() ? "" : ", ") + var.name + "=" + domain_.constants(var.type)[static_cast<std::size_t>(value)];
  }
  throw MlnError("hard rule " + c.describe() + " is unsatisfiable under the evidence" +
                 (where.empty() ? std::string() : " for " + where));
}

}  // namespace ksmc::runtime::mln
