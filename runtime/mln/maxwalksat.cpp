#include "runtime/mln/maxwalksat.h"

#include <set>
#include <string>

#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {
namespace {

bool better(const Delta& a, const Delta& b) {
  if (a.hard != b.hard) return a.hard < b.hard;
  return a.soft < b.soft;
}

struct Move {
  AtomId atom = -1;     // flip this atom (not in a block) ...
  std::int32_t block = -1;
  AtomId to = -1;       // ... or move block's true atom here
};

bool improves(const Delta& d) { return d.hard < 0 || (d.hard == 0 && d.soft < -1e-9); }

// Steepest-order local search to a 1-flip optimum: WalkSAT only flips atoms of bad clauses,
// so a state can end a try with an atom whose flip would improve satisfied clauses' cost
// (e.g. a unit prior like `!supported(o)` outweighed by nothing). Deterministic order.
void greedy_descent(LocalState& st) {
  const GroundNetwork& net = st.network();
  for (bool changed = true; changed;) {
    changed = false;
    io::throw_if_cancelled("MaxWalkSAT");
    for (AtomId a = 0; a < net.num_atoms(); ++a) {
      const std::int32_t b = net.block_of(a);
      if (b < 0) {
        if (improves(st.flip_delta(a))) {
          st.flip(a);
          changed = true;
        }
      } else if (!st.value(a) && improves(st.move_delta(b, a))) {
        st.move(b, a);
        changed = true;
      }
    }
  }
  st.refresh_cost();
}

}  // namespace

bool walksat_step(LocalState& st, Rng& rng, double noise) {
  if (st.num_bad() == 0) return false;
  const GroundNetwork& net = st.network();
  const std::int32_t c = st.bad(static_cast<std::int32_t>(rng.below(static_cast<std::uint32_t>(st.num_bad()))));
  const bool want_sat = st.wants_sat(c);
  // Candidate moves: change a literal's truth in the direction the clause wants.
  Move cand[64];
  std::int32_t nc = 0;
  for (Lit l : net.clause(c)) {
    const AtomId a = lit_atom(l);
    const bool is_true = lit_true(l, st.value(a));
    if (is_true == want_sat) continue;  // already as wanted (only for want_unsat: false lits)
    const std::int32_t b = net.block_of(a);
    if (b < 0) {
      if (nc < 64) cand[nc++] = {a, -1, -1};
    } else if (!st.value(a)) {
      if (nc < 64) cand[nc++] = {-1, b, a};  // make a the block's true atom
    } else {
      for (AtomId o : net.block(b))  // move the block away from a
        if (o != a && nc < 64) cand[nc++] = {-1, b, o};
    }
  }
  if (nc == 0) return false;
  std::int32_t pick = 0;
  if (rng.coin(noise)) {
    pick = static_cast<std::int32_t>(rng.below(static_cast<std::uint32_t>(nc)));
  } else {
    Delta best;
    std::int32_t ties = 0;
    for (std::int32_t i = 0; i < nc; ++i) {
      const Delta d = cand[i].atom >= 0 ? st.flip_delta(cand[i].atom) : st.move_delta(cand[i].block, cand[i].to);
      if (i == 0 || better(d, best)) {
        best = d;
        pick = i;
        ties = 1;
      } else if (!better(best, d) && rng.below(static_cast<std::uint32_t>(++ties)) == 0) {
        pick = i;  // reservoir choice among equal moves
      }
    }
  }
  if (cand[pick].atom >= 0) st.flip(cand[pick].atom);
  else st.move(cand[pick].block, cand[pick].to);
  return true;
}

MapResult max_walksat(const GroundNetwork& net, const MapOptions& options) {
  const Occurrences occ = build_occurrences(net);
  LocalState st(net, occ);
  Rng rng(options.seed);
  MapResult best;
  const std::int64_t stall = options.stall_flips > 0 ? options.stall_flips : 1000 + 20 * std::int64_t{net.num_clauses()};
  std::int32_t best_hard = -1;
  double best_soft = 0.0;
  for (std::int32_t t = 0; t < std::max<std::int32_t>(1, options.tries); ++t) {
    st.randomize(rng);
    std::int64_t last_improvement = 0;
    for (std::int64_t f = 0;; ++f) {
      if (best_hard < 0 || st.hard_bad() < best_hard ||
          (st.hard_bad() == best_hard && st.soft_cost() < best_soft - 1e-12)) {
        best_hard = st.hard_bad();
        best_soft = st.soft_cost();
        best.state = st.values();
        last_improvement = f;
      }
      if (st.num_bad() == 0 || f >= options.max_flips || f - last_improvement > stall) break;
      if ((f & 1023) == 1023) io::throw_if_cancelled("MaxWalkSAT");
      walksat_step(st, rng, options.noise);
      ++best.flips;
      if ((f & 1023) == 1023) st.refresh_cost();
    }
    // Polish the best state so far to a local optimum of single flips / block moves.
    st.assign(best.state);
    greedy_descent(st);
    if (st.hard_bad() < best_hard || (st.hard_bad() == best_hard && st.soft_cost() < best_soft - 1e-12)) {
      best_hard = st.hard_bad();
      best_soft = st.soft_cost();
      best.state = st.values();
    }
    if (best_hard == 0 && best_soft <= 0.0) break;  // nothing left to gain
  }
  best.feasible = net.feasible(best.state);
  best.log_weight = net.log_weight(best.state);
  return best;
}

std::vector<std::uint8_t> find_feasible_state(const GroundNetwork& net, const Occurrences& occ, Rng& rng,
                                              std::int64_t max_flips) {
  LocalState st(net, occ);
  std::vector<double> cost(static_cast<std::size_t>(net.num_clauses()), 0.0);
  std::vector<std::uint8_t> want(static_cast<std::size_t>(net.num_clauses()), 1);
  for (std::int32_t c = 0; c < net.num_clauses(); ++c)
    if (net.is_hard(c)) cost[c] = 1.0;
  st.set_objective(cost, want);
  std::int64_t flips = 0;
  std::int32_t best_bad = -1;
  std::vector<std::uint8_t> best_state;
  while (flips < max_flips) {
    st.randomize(rng);
    for (std::int64_t f = 0; f < 10000 + 10 * net.num_atoms() && flips < max_flips; ++f, ++flips) {
      if (st.num_bad() == 0) return st.values();
      if ((f & 1023) == 1023) io::throw_if_cancelled("finding a state that satisfies the hard rules");
      walksat_step(st, rng, 0.2);
    }
    if (st.num_bad() == 0) return st.values();
    if (best_bad < 0 || st.num_bad() < best_bad) {
      best_bad = st.num_bad();
      best_state = st.values();
    }
  }
  st.assign(best_state);
  std::set<std::string> rules;
  for (std::int32_t i = 0; i < st.num_bad(); ++i) rules.insert(net.origin_name(st.bad(i)));
  std::string list;
  for (const auto& r : rules) list += (list.empty() ? "" : ", ") + r;
  throw MlnError("no state satisfying the hard constraints found after " + std::to_string(max_flips) +
                 " flips; still violated: " + list);
}

}  // namespace ksmc::runtime::mln
