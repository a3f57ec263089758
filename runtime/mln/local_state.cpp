#include "runtime/mln/local_state.h"

#include <cmath>

namespace ksmc::runtime::mln {

LocalState::LocalState(const GroundNetwork& net, const Occurrences& occ) : net_(net), occ_(occ) {
  const auto n = static_cast<std::size_t>(net.num_atoms());
  const auto m = static_cast<std::size_t>(net.num_clauses());
  value_.assign(n, 0);
  count_.assign(m, 0);
  cost_.assign(m, 0.0);
  hard_.assign(m, 0);
  want_sat_.assign(m, 1);
  bad_pos_.assign(m, -1);
  block_true_.assign(static_cast<std::size_t>(net.num_blocks()), -1);
  use_network_objective();
}

void LocalState::use_network_objective() {
  for (std::int32_t c = 0; c < net_.num_clauses(); ++c) {
    hard_[c] = net_.is_hard(c) ? 1 : 0;
    cost_[c] = hard_[c] ? 1.0 : std::abs(net_.weight(c));
    want_sat_[c] = (hard_[c] || net_.weight(c) > 0.0) ? 1 : 0;
  }
  rebuild_bad();
}

void LocalState::set_objective(std::span<const double> cost, std::span<const std::uint8_t> want_sat) {
  for (std::int32_t c = 0; c < net_.num_clauses(); ++c) {
    hard_[c] = 0;
    cost_[c] = cost[c];
    want_sat_[c] = want_sat[c];
  }
  rebuild_bad();
}

void LocalState::rebuild_bad() {
  for (std::int32_t c : bad_) bad_pos_[c] = -1;
  bad_.clear();
  hard_bad_ = 0;
  soft_cost_ = 0.0;
  for (std::int32_t c = 0; c < net_.num_clauses(); ++c) {
    if (!is_bad(c)) continue;
    bad_pos_[c] = static_cast<std::int32_t>(bad_.size());
    bad_.push_back(c);
    if (hard_[c]) ++hard_bad_; else soft_cost_ += cost_[c];
  }
}

void LocalState::refresh_cost() {
  soft_cost_ = 0.0;
  for (std::int32_t c : bad_)
    if (!hard_[c]) soft_cost_ += cost_[c];
}

void LocalState::assign(std::span<const std::uint8_t> values) {
  for (std::size_t a = 0; a < value_.size(); ++a) value_[a] = values[a] ? 1 : 0;
  for (std::int32_t c = 0; c < net_.num_clauses(); ++c) {
    std::int32_t k = 0;
    for (Lit l : net_.clause(c)) k += lit_true(l, value_[lit_atom(l)]) ? 1 : 0;
    count_[c] = k;
  }
  for (std::int32_t b = 0; b < net_.num_blocks(); ++b) {
    block_true_[b] = -1;
    for (AtomId a : net_.block(b))
      if (value_[a]) block_true_[b] = a;
  }
  rebuild_bad();
}

void LocalState::randomize(Rng& rng) {
  std::vector<std::uint8_t> v(value_.size());
  for (auto& x : v) x = static_cast<std::uint8_t>(rng.next() >> 63);
  for (std::int32_t b = 0; b < net_.num_blocks(); ++b) {
    const auto atoms = net_.block(b);
    for (AtomId a : atoms) v[a] = 0;
    v[atoms[rng.below(static_cast<std::uint32_t>(atoms.size()))]] = 1;
  }
  assign(v);
}

void LocalState::set_bad(std::int32_t c, bool bad) {
  if (bad) {
    bad_pos_[c] = static_cast<std::int32_t>(bad_.size());
    bad_.push_back(c);
    if (hard_[c]) ++hard_bad_; else soft_cost_ += cost_[c];
  } else {
    const std::int32_t pos = bad_pos_[c];
    const std::int32_t last = bad_.back();
    bad_[pos] = last;
    bad_pos_[last] = pos;
    bad_.pop_back();
    bad_pos_[c] = -1;
    if (hard_[c]) --hard_bad_; else soft_cost_ -= cost_[c];
  }
}

Delta LocalState::flip_delta(AtomId a) const {
  Delta d;
  const std::uint8_t nv = value_[a] ? 0 : 1;
  for (std::int32_t k = occ_.offsets[a]; k < occ_.offsets[a + 1]; ++k) {
    const std::int32_t c = occ_.clause[k];
    if (cost_[c] <= 0.0) continue;
    const bool becomes_true = (nv != 0) != (occ_.negated[k] != 0);
    const std::int32_t before = count_[c];
    const std::int32_t after = before + (becomes_true ? 1 : -1);
    if ((before > 0) == (after > 0)) continue;
    const bool bad_before = (before > 0) != (want_sat_[c] != 0);
    const int sign = bad_before ? -1 : 1;
    if (hard_[c]) d.hard += sign; else d.soft += sign * cost_[c];
  }
  return d;
}

void LocalState::flip(AtomId a) {
  const std::uint8_t nv = value_[a] ? 0 : 1;
  value_[a] = nv;
  for (std::int32_t k = occ_.offsets[a]; k < occ_.offsets[a + 1]; ++k) {
    const std::int32_t c = occ_.clause[k];
    const bool becomes_true = (nv != 0) != (occ_.negated[k] != 0);
    const std::int32_t before = count_[c];
    count_[c] = before + (becomes_true ? 1 : -1);
    if ((before > 0) == (count_[c] > 0) || cost_[c] <= 0.0) continue;
    set_bad(c, (count_[c] > 0) != (want_sat_[c] != 0));
  }
}

Delta LocalState::move_delta(std::int32_t b, AtomId to) {
  const AtomId from = block_true_[b];
  if (from == to) return {};
  Delta d1 = flip_delta(from);
  flip(from);
  const Delta d2 = flip_delta(to);
  flip(from);
  d1.hard += d2.hard;
  d1.soft += d2.soft;
  return d1;
}

void LocalState::move(std::int32_t b, AtomId to) {
  const AtomId from = block_true_[b];
  if (from == to) return;
  flip(from);
  flip(to);
  block_true_[b] = to;
}

VarList make_var_list(const GroundNetwork& net) {
  VarList v;
  for (AtomId a = 0; a < net.num_atoms(); ++a)
    if (net.block_of(a) < 0) v.atoms.push_back(a);
  v.num_blocks = net.num_blocks();
  return v;
}

}  // namespace ksmc::runtime::mln
