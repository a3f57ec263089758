#include "runtime/mln/ground_bound.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <set>


namespace ksmc::runtime::mln {
namespace {

std::atomic<std::uint64_t> g_limit{kDefaultMaxGroundClauses};

// 50,000,000 below 10^15; 2.25e+15 above.
std::string count_text(double n) {
  if (n >= 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", n);
    return buf;
  }
  std::string digits = std::to_string(static_cast<std::uint64_t>(n));
  for (auto i = static_cast<std::ptrdiff_t>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<std::size_t>(i), ",");
  return digits;
}

// Atoms of evidence predicate p with value `value` (closed world: unknown reads false).
double count_atoms(const Evidence& evidence, std::int32_t p, bool value) {
  std::int64_t n = 0;
  for (std::int64_t f = 0; f < evidence.num_atoms(p); ++f) n += (evidence.get_flat(p, f) == 1) == value ? 1 : 0;
  return static_cast<double>(n);
}

}  // namespace

void set_max_ground_clauses(std::uint64_t limit) noexcept { g_limit.store(limit); }
std::uint64_t max_ground_clauses() noexcept { return g_limit.load(); }

GroundEstimate estimate_ground_clauses(const Program& program, const Domain& domain, const Evidence& evidence,
                                       const Clause& clause) {
  GroundEstimate e;
  for (const auto& v : clause.variables) {
    if (v.existential) continue;
    const auto n = domain.size(v.type);
    e.bindings *= static_cast<double>(n);
    if (!e.binding.empty()) e.binding += " x ";
    e.binding += v.name + ":" + program.types[static_cast<std::size_t>(v.type)] + "(" + std::to_string(n) + ")";
  }
  e.clauses = e.bindings;
  for (const auto& lit : clause.literals) {
    const auto& pred = program.predicates[static_cast<std::size_t>(lit.predicate)];
    if (pred.query) continue;
    std::set<std::int32_t> in_literal;
    for (const auto& t : lit.args) {
      if (!t.is_variable || clause.variables[static_cast<std::size_t>(t.variable)].existential) continue;
      in_literal.insert(t.variable);
    }
    if (in_literal.size() != lit.args.size()) continue;  // constants or existentials: no simple bound
    double rest = 1.0;
    for (std::size_t v = 0; v < clause.variables.size(); ++v)
      if (!clause.variables[v].existential && !in_literal.contains(static_cast<std::int32_t>(v)))
        rest *= static_cast<double>(domain.size(clause.variables[v].type));
    // The literal is false (the grounding survives) where the atom has value !negated.
    e.clauses = std::min(e.clauses, count_atoms(evidence, lit.predicate, lit.negated) * rest);
  }
  return e;
}

void check_ground_bound(const Program& program, const Domain& domain, const Evidence& evidence) {
  const std::uint64_t limit = max_ground_clauses();
  if (limit == 0) return;
  const auto lim = static_cast<double>(limit);
  double total = 0.0;
  for (const auto& c : program.clauses) {
    const GroundEstimate e = estimate_ground_clauses(program, domain, evidence, c);
    if (e.clauses > lim) {
      throw GroundingTooLarge("rule " + c.describe() + " would ground to up to " + count_text(e.clauses) +
                     " clauses after evidence folding (binding " + e.binding + " = " + count_text(e.bindings) +
                     " groundings), above the limit of " + count_text(lim) +
                     "; raise it with --max-ground-clauses N, or add evidence / shrink the domains");
    }
    total += e.clauses;
  }
  if (total > lim) {
    throw GroundingTooLarge("the rules together would ground to up to " + count_text(total) +
                   " clauses after evidence folding, above the limit of " + count_text(lim) +
                   "; raise it with --max-ground-clauses N");
  }
}

}  // namespace ksmc::runtime::mln
