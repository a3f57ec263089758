#include "runtime/mln/ground_network.h"

#include <algorithm>

#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {

AtomId GroundNetwork::add_atom(std::int32_t label) {
  block_of_.push_back(-1);
  labels_.push_back(label);
  return static_cast<AtomId>(block_of_.size() - 1);
}

void GroundNetwork::add_atoms(std::int32_t count, std::int32_t label) {
  block_of_.resize(block_of_.size() + static_cast<std::size_t>(count), -1);
  labels_.resize(labels_.size() + static_cast<std::size_t>(count), label);
}

void GroundNetwork::push_clause(std::span<const Lit> lits, double weight, std::int32_t origin) {
  scratch_.assign(lits.begin(), lits.end());
  for (Lit l : scratch_) {
    if (l < 0 || lit_atom(l) >= num_atoms()) {
      throw MlnError("ground network: literal " + std::to_string(l) + " names atom " +
                     std::to_string(lit_atom(l)) + " but the network has " +
                     std::to_string(num_atoms()) + " atoms");
    }
  }
  std::sort(scratch_.begin(), scratch_.end());
  scratch_.erase(std::unique(scratch_.begin(), scratch_.end()), scratch_.end());
  for (std::size_t i = 1; i < scratch_.size(); ++i) {
    if (lit_atom(scratch_[i]) == lit_atom(scratch_[i - 1])) {  // a v !a
      if (!std::isinf(weight)) constant_ += weight;
      return;
    }
  }
  if (scratch_.empty()) {
    if (std::isinf(weight)) {
      throw MlnError("ground network: empty hard clause" +
                     (origin >= 0 ? " from " + (origin < static_cast<std::int32_t>(origin_names_.size())
                                                    ? origin_names_[origin]
                                                    : "rule " + std::to_string(origin))
                                  : std::string()) +
                     ": the hard constraints are unsatisfiable");
    }
    return;  // a soft clause that can never be satisfied contributes nothing
  }
  if (weight == 0.0) return;
  lits_.insert(lits_.end(), scratch_.begin(), scratch_.end());
  offsets_.push_back(static_cast<std::int32_t>(lits_.size()));
  weights_.push_back(weight);
  origins_.push_back(origin);
  if (std::isinf(weight)) ++num_hard_;
}

void GroundNetwork::add_clause(std::span<const Lit> lits, double weight, std::int32_t origin) {
  if (std::isnan(weight) || std::isinf(weight)) {
    throw MlnError("ground network: soft clause weight must be finite (use add_hard_clause)");
  }
  push_clause(lits, weight, origin);
}

void GroundNetwork::add_hard_clause(std::span<const Lit> lits, std::int32_t origin) {
  push_clause(lits, kHardWeight, origin);
}

void GroundNetwork::add_exactly_one(std::span<const AtomId> atoms, std::int32_t origin) {
  if (atoms.empty()) throw MlnError("ground network: empty exactly-one block is unsatisfiable");
  for (AtomId a : atoms) {
    if (a < 0 || a >= num_atoms()) {
      throw MlnError("ground network: exactly-one block names atom " + std::to_string(a) +
                     " but the network has " + std::to_string(num_atoms()) + " atoms");
    }
    if (block_of_[a] >= 0) {
      throw MlnError("ground network: atom " + std::to_string(a) + " (" + label_name(a) +
                     ") is in two exactly-one blocks");
    }
  }
  if (atoms.size() == 1) {
    const Lit l = make_lit(atoms[0], false);
    push_clause(std::span<const Lit>(&l, 1), kHardWeight, origin);
    return;
  }
  const std::int32_t b = num_blocks();
  for (AtomId a : atoms) {
    if (block_of_[a] >= 0) throw MlnError("ground network: duplicate atom in exactly-one block");
    block_of_[a] = b;
    block_atoms_.push_back(a);
  }
  block_offsets_.push_back(static_cast<std::int32_t>(block_atoms_.size()));
}

std::string GroundNetwork::label_name(AtomId a) const {
  const std::int32_t l = labels_[a];
  if (l >= 0 && l < static_cast<std::int32_t>(label_names_.size())) return label_names_[l];
  return "atom " + std::to_string(a);
}

std::string GroundNetwork::origin_name(std::int32_t c) const {
  const std::int32_t o = origins_[c];
  if (o >= 0 && o < static_cast<std::int32_t>(origin_names_.size())) return origin_names_[o];
  return "clause " + std::to_string(c);
}

bool GroundNetwork::feasible(std::span<const std::uint8_t> state) const {
  for (std::int32_t b = 0; b < num_blocks(); ++b) {
    int on = 0;
    for (AtomId a : block(b)) on += state[a] != 0;
    if (on != 1) return false;
  }
  for (std::int32_t c = 0; c < num_clauses(); ++c) {
    if (!is_hard(c)) continue;
    bool sat = false;
    for (Lit l : clause(c)) sat = sat || lit_true(l, state[lit_atom(l)]);
    if (!sat) return false;
  }
  return true;
}

double GroundNetwork::log_weight(std::span<const std::uint8_t> state) const {
  if (!feasible(state)) return -std::numeric_limits<double>::infinity();
  double s = constant_;
  for (std::int32_t c = 0; c < num_clauses(); ++c) {
    if (is_hard(c)) continue;
    bool sat = false;
    for (Lit l : clause(c)) sat = sat || lit_true(l, state[lit_atom(l)]);
    if (sat) s += weights_[c];
  }
  return s;
}

void GroundNetwork::clear() {
  lits_.clear();
  offsets_.assign(1, 0);
  weights_.clear();
  origins_.clear();
  num_hard_ = 0;
  block_atoms_.clear();
  block_offsets_.assign(1, 0);
  block_of_.clear();
  labels_.clear();
  constant_ = 0.0;
}

Occurrences build_occurrences(const GroundNetwork& net) {
  Occurrences occ;
  const std::int32_t n = net.num_atoms();
  occ.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  for (std::int32_t c = 0; c < net.num_clauses(); ++c)
    for (Lit l : net.clause(c)) ++occ.offsets[lit_atom(l) + 1];
  for (std::int32_t a = 0; a < n; ++a) occ.offsets[a + 1] += occ.offsets[a];
  occ.clause.resize(occ.offsets[n]);
  occ.negated.resize(occ.offsets[n]);
  std::vector<std::int32_t> fill(occ.offsets.begin(), occ.offsets.end() - 1);
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    for (Lit l : net.clause(c)) {
      const std::int32_t pos = fill[lit_atom(l)]++;
      occ.clause[pos] = c;
      occ.negated[pos] = lit_negated(l) ? 1 : 0;
    }
  }
  return occ;
}

}  // namespace ksmc::runtime::mln
