// The ground Markov network all inference engines run on.
//
// Free atoms are 0..n-1. A literal is an int32 `atom * 2 + negated`. Clauses are
// disjunctions of literals stored in one flat array with offsets; each has a weight
// (hard clauses have weight +inf). Exactly-one blocks are kept as constraints that
// every engine respects structurally (never as clauses). `constant()` is the
// log-weight contributed by clauses that evidence folding found always satisfied.
//
// The log-weight of a state x that satisfies all hard clauses and blocks is
//   constant() + sum_{soft clauses c satisfied by x} weight(c).
//
// Builder API (used by the generic grounder and by generated grounding code):
//   add_atom, add_clause(lits, weight), add_hard_clause(lits), add_exactly_one(atoms).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace ksmc::runtime::mln {

using Lit = std::int32_t;
using AtomId = std::int32_t;

constexpr Lit make_lit(AtomId atom, bool negated) { return atom * 2 + (negated ? 1 : 0); }
constexpr AtomId lit_atom(Lit l) { return l >> 1; }
constexpr bool lit_negated(Lit l) { return (l & 1) != 0; }
// True when literal `l` is satisfied by atom value `v` (0/1).
constexpr bool lit_true(Lit l, std::uint8_t v) { return (v != 0) != lit_negated(l); }

constexpr double kHardWeight = std::numeric_limits<double>::infinity();

class GroundNetwork {
 public:
  // Adds a free atom. `label` is an optional small id (e.g. the predicate) used only
  // to make error messages readable; see set_label_names.
  AtomId add_atom(std::int32_t label = -1);
  void add_atoms(std::int32_t count, std::int32_t label = -1);

  // Adds a weighted clause. Literals are sorted and deduplicated; a tautology adds its
  // weight to the constant; an empty soft clause is dropped (never satisfied).
  // `origin` is an optional rule id for messages (see set_origin_names).
  void add_clause(std::span<const Lit> lits, double weight, std::int32_t origin = -1);
  // Adds a hard clause; an empty one throws MlnError (unsatisfiable).
  void add_hard_clause(std::span<const Lit> lits, std::int32_t origin = -1);
  // Exactly one of `atoms` is true. Each atom may belong to at most one block;
  // a one-atom block makes that atom always true (stored as a hard unit clause).
  void add_exactly_one(std::span<const AtomId> atoms, std::int32_t origin = -1);
  void add_constant(double log_weight) { constant_ += log_weight; }

  void set_label_names(std::vector<std::string> names) { label_names_ = std::move(names); }
  void set_origin_names(std::vector<std::string> names) { origin_names_ = std::move(names); }
  const std::vector<std::string>& label_names() const { return label_names_; }
  const std::vector<std::string>& origin_names() const { return origin_names_; }

  // ---- read access ----
  std::int32_t num_atoms() const { return static_cast<std::int32_t>(block_of_.size()); }
  std::int32_t num_clauses() const { return static_cast<std::int32_t>(weights_.size()); }
  std::span<const Lit> clause(std::int32_t c) const {
    return {lits_.data() + offsets_[c], lits_.data() + offsets_[c + 1]};
  }
  double weight(std::int32_t c) const { return weights_[c]; }
  bool is_hard(std::int32_t c) const { return std::isinf(weights_[c]); }
  std::int32_t origin(std::int32_t c) const { return origins_[c]; }
  std::int32_t num_hard() const { return num_hard_; }
  double constant() const { return constant_; }

  std::int32_t num_blocks() const { return static_cast<std::int32_t>(block_offsets_.size()) - 1; }
  std::span<const AtomId> block(std::int32_t b) const {
    return {block_atoms_.data() + block_offsets_[b], block_atoms_.data() + block_offsets_[b + 1]};
  }
  std::int32_t block_of(AtomId a) const { return block_of_[a]; }
  std::int32_t label(AtomId a) const { return labels_[a]; }

  // "supported" for labelled atoms, "atom 17" otherwise.
  std::string label_name(AtomId a) const;
  // "r10 (tabletop.ksm:14)" when origin names were given, "clause 3" otherwise.
  std::string origin_name(std::int32_t c) const;

  // Log-weight of a full state (values 0/1 per atom); -inf if a hard clause or a
  // block is violated.
  double log_weight(std::span<const std::uint8_t> state) const;
  // True when every hard clause and every block is satisfied.
  bool feasible(std::span<const std::uint8_t> state) const;

  void clear();

 private:
  void push_clause(std::span<const Lit> lits, double weight, std::int32_t origin);

  std::vector<Lit> lits_;
  std::vector<std::int32_t> offsets_{0};
  std::vector<double> weights_;
  std::vector<std::int32_t> origins_;
  std::int32_t num_hard_ = 0;
  std::vector<AtomId> block_atoms_;
  std::vector<std::int32_t> block_offsets_{0};
  std::vector<std::int32_t> block_of_;
  std::vector<std::int32_t> labels_;
  std::vector<Lit> scratch_;
  double constant_ = 0.0;
  std::vector<std::string> label_names_;
  std::vector<std::string> origin_names_;
};

// Atom -> clause occurrence lists (CSR), built once per network by the engines.
struct Occurrences {
  std::vector<std::int32_t> offsets;  // size num_atoms + 1
  std::vector<std::int32_t> clause;   // clause index
  std::vector<std::uint8_t> negated;  // the literal's sign in that clause
  std::span<const std::int32_t> clauses_of(AtomId a) const {
    return {clause.data() + offsets[a], clause.data() + offsets[a + 1]};
  }
};
Occurrences build_occurrences(const GroundNetwork& net);

}  // namespace ksmc::runtime::mln
