// Small hand-built networks and helpers shared by the sampler tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "runtime/mln/ground_network.h"

namespace ksmc::tests::mln {

// The mode of a small network by plain enumeration of all 2^n states (no blocks logic
// beyond GroundNetwork::log_weight). `unique` is false if the best two are within 1e-6.
struct ModeResult {
  std::vector<std::uint8_t> state;
  double log_weight = -std::numeric_limits<double>::infinity();
  bool unique = false;
};

inline ModeResult enumerate_mode(const runtime::mln::GroundNetwork& net) {
  const auto n = net.num_atoms();
  ModeResult best;
  double second = -std::numeric_limits<double>::infinity();
  std::vector<std::uint8_t> s(static_cast<std::size_t>(n));
  for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << n); ++mask) {
    for (std::int32_t a = 0; a < n; ++a) s[a] = (mask >> a) & 1;
    const double w = net.log_weight(s);
    if (w > best.log_weight) {
      second = best.log_weight;
      best.log_weight = w;
      best.state = s;
    } else if (w > second) {
      second = w;
    }
  }
  best.unique = best.log_weight - second > 1e-6;
  return best;
}

// A mixed network: a 3-way block, a 2-way block, free atoms, soft clauses of both
// signs and hard clauses that leave every block value reachable one move at a time.
inline runtime::mln::GroundNetwork mixed_network() {
  using namespace runtime::mln;
  GroundNetwork net;
  net.add_atoms(9);
  const AtomId b3[] = {0, 1, 2};
  const AtomId b2[] = {3, 4};
  net.add_exactly_one(b3);
  net.add_exactly_one(b2);
  auto soft = [&](std::initializer_list<Lit> l, double w) { net.add_clause(std::vector<Lit>(l), w); };
  auto hard = [&](std::initializer_list<Lit> l) { net.add_hard_clause(std::vector<Lit>(l)); };
  soft({make_lit(0, false)}, 0.8);
  soft({make_lit(1, true), make_lit(5, false)}, 1.2);
  soft({make_lit(5, true), make_lit(6, false), make_lit(3, false)}, 0.7);
  soft({make_lit(6, false), make_lit(7, false)}, -0.9);
  soft({make_lit(7, true), make_lit(8, false)}, 1.5);
  soft({make_lit(2, false), make_lit(8, true)}, 0.6);
  soft({make_lit(4, false)}, 0.3);
  hard({make_lit(0, true), make_lit(7, false), make_lit(8, false)});  // 0 => 7 v 8
  hard({make_lit(4, true), make_lit(5, true), make_lit(6, false)});   // 4 ^ 5 => 6
  return net;
}

// Hard equivalences (like SaLe(a,b) <=> SaLe(b,a)): atoms 0 <=> 1 and 2 <=> !3, with
// soft fields; single-site Gibbs could never move these atoms.
inline runtime::mln::GroundNetwork equivalence_network() {
  using namespace runtime::mln;
  GroundNetwork net;
  net.add_atoms(5);
  auto soft = [&](std::initializer_list<Lit> l, double w) { net.add_clause(std::vector<Lit>(l), w); };
  auto hard = [&](std::initializer_list<Lit> l) { net.add_hard_clause(std::vector<Lit>(l)); };
  hard({make_lit(0, true), make_lit(1, false)});
  hard({make_lit(0, false), make_lit(1, true)});
  hard({make_lit(2, false), make_lit(3, false)});
  hard({make_lit(2, true), make_lit(3, true)});
  soft({make_lit(0, false)}, 1.0);
  soft({make_lit(1, false)}, -0.4);
  soft({make_lit(1, true), make_lit(4, false)}, 0.8);
  soft({make_lit(3, false), make_lit(4, true)}, 1.3);
  soft({make_lit(2, false)}, 0.2);
  return net;
}

}  // namespace ksmc::tests::mln
