// Incremental clause bookkeeping shared by the stochastic engines (MaxWalkSAT,
// SampleSAT/MC-SAT, Gibbs, AIS): atom values, satisfied-literal counts per clause,
// and the list of "bad" clauses under a configurable objective.
//
// Each clause has a cost (0 = ignored), a hard flag and a wanted polarity: a clause
// is bad when it is active and (satisfied != wants_satisfied). The state tracks the
// number of bad hard clauses and the summed cost of bad soft clauses, so objectives
// compare lexicographically (hard first) without a huge "hard weight".
//
// With cost |w|, polarity (w > 0) and hard flags from the network, the log-weight of
// a feasible state is  constant + sum_{w>0} w - soft_cost()  (a constant shift).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "runtime/mln/ground_network.h"
#include "runtime/mln/rng.h"

namespace ksmc::runtime::mln {

struct Delta {
  std::int32_t hard = 0;
  double soft = 0.0;
};

class LocalState {
 public:
  LocalState(const GroundNetwork& net, const Occurrences& occ);

  // Objective from the network: soft cost |w|, polarity w > 0, hard clauses hard.
  void use_network_objective();
  // Custom objective (SampleSAT): cost[c] (0 = inactive), want_sat[c]; all soft.
  void set_objective(std::span<const double> cost, std::span<const std::uint8_t> want_sat);

  // Sets all values (recomputes counts and the bad list).
  void assign(std::span<const std::uint8_t> values);
  // A random state respecting the blocks.
  void randomize(Rng& rng);

  Delta flip_delta(AtomId a) const;
  void flip(AtomId a);
  // Delta of moving block b's true atom to `to` (exactly-one kept); does not change state.
  Delta move_delta(std::int32_t b, AtomId to);
  void move(std::int32_t b, AtomId to);
  // The block's currently true atom.
  AtomId block_true(std::int32_t b) const { return block_true_[b]; }

  std::int32_t hard_bad() const { return hard_bad_; }
  double soft_cost() const { return soft_cost_; }
  std::int32_t num_bad() const { return static_cast<std::int32_t>(bad_.size()); }
  std::int32_t bad(std::int32_t i) const { return bad_[i]; }
  std::int32_t sat_count(std::int32_t c) const { return count_[c]; }
  bool wants_sat(std::int32_t c) const { return want_sat_[c] != 0; }
  const std::vector<std::uint8_t>& values() const { return value_; }
  std::uint8_t value(AtomId a) const { return value_[a]; }

  const GroundNetwork& network() const { return net_; }
  // Recomputes soft_cost from scratch (call now and then to stop float drift).
  void refresh_cost();

 private:
  bool is_bad(std::int32_t c) const {
    return cost_[c] > 0.0 && ((count_[c] > 0) != (want_sat_[c] != 0));
  }
  void set_bad(std::int32_t c, bool bad);
  void rebuild_bad();

  const GroundNetwork& net_;
  const Occurrences& occ_;
  std::vector<std::uint8_t> value_;
  std::vector<std::int32_t> count_;
  std::vector<double> cost_;
  std::vector<std::uint8_t> hard_;
  std::vector<std::uint8_t> want_sat_;
  std::vector<std::int32_t> bad_;
  std::vector<std::int32_t> bad_pos_;  // -1 when not bad
  std::vector<AtomId> block_true_;
  std::int32_t hard_bad_ = 0;
  double soft_cost_ = 0.0;
};

// Variables of the stochastic engines: free atoms outside blocks, then blocks.
struct VarList {
  std::vector<AtomId> atoms;    // atoms not in any block
  std::int32_t num_blocks = 0;
  std::int32_t size() const { return static_cast<std::int32_t>(atoms.size()) + num_blocks; }
};
VarList make_var_list(const GroundNetwork& net);

}  // namespace ksmc::runtime::mln
