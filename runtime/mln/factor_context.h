// What generated grounding code (`<domain>_factors.cpp`, see compiler/emit) calls while it
// grounds one clause: domain sizes, evidence lookups, folding of query literals against
// fixed atoms, and adding the folded clause to the network. The generic grounder and the
// generated code share `prepare_grounding` (query index, exactly-one blocks, free atoms),
// so both produce the same network, and both end with `fold_forced_atoms`.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "runtime/io/cancel.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/forced_atoms.h"
#include "runtime/mln/grounder.h"

namespace ksmc::runtime::mln {

class FactorContext {
 public:
  FactorContext(Grounding& grounding, const Evidence& evidence)
      : g_(grounding), evidence_(evidence), domain_(*grounding.domain) {}

  std::int32_t size(std::int32_t type) const { return domain_.size(type); }

  // Value of an evidence atom (closed world: not given true reads false).
  bool ev(std::int32_t predicate, std::int64_t flat) const { return evidence_.get_flat(predicate, flat) == 1; }

  // Starts the next grounding of the current clause.
  void begin() {
    if ((++groundings_ & 0xFFFF) == 0) io::throw_if_cancelled("grounding");
    lits_.clear();
  }

  // Adds the literal over query atom p(flat) to the clause being built. Returns true when
  // the atom is fixed (by evidence or a folded block) so that the literal is true: the
  // clause is satisfied. A fixed false literal is dropped.
  bool query(std::int32_t predicate, std::int64_t flat, bool negated) {
    const std::int64_t q = g_.index.offset[static_cast<std::size_t>(predicate)] + flat;
    const AtomId atom = g_.index.atom[static_cast<std::size_t>(q)];
    if (atom < 0) return (g_.index.fixed[static_cast<std::size_t>(q)] == 1) != negated;
    lits_.push_back(make_lit(atom, negated));
    return false;
  }

  // A soft clause satisfied by the evidence in `count` groundings adds its weight each time.
  void satisfied(double weight, std::int64_t count = 1) {
    g_.network.add_constant(weight * static_cast<double>(count));
  }

  // Ends a grounding of soft clause `clause` (index in the program): adds what is left.
  void soft(double weight, std::int32_t clause) {
    if (!lits_.empty()) g_.network.add_clause(lits_, weight, clause);
  }

  // Ends a grounding of hard clause `clause`; `binding` holds the value of every clause
  // variable (existential ones ignored). Throws MlnError naming the rule and the binding
  // when the evidence falsified every literal.
  void hard(std::int32_t clause, std::initializer_list<std::int32_t> binding);

 private:
  Grounding& g_;
  const Evidence& evidence_;
  const Domain& domain_;
  std::vector<Lit> lits_;
  std::uint32_t groundings_ = 0;  // polls the cancel flag every 65,536 groundings
};

}  // namespace ksmc::runtime::mln
