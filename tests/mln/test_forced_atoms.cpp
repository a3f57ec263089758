// fold_forced_atoms: atoms forced by hard unit clauses (and by unit propagation) leave
// the network; marginals and log Z stay those of the unfolded network.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/forced_atoms.h"

using namespace ksmc::runtime::mln;

namespace {

// A grounding whose query atoms are the network's atoms, one to one.
Grounding identity_grounding(GroundNetwork net) {
  Grounding g;
  const auto n = net.num_atoms();
  g.network = std::move(net);
  g.index.offset = {0};
  g.index.num_query_atoms = n;
  for (AtomId a = 0; a < n; ++a) {
    g.index.atom.push_back(a);
    g.index.fixed.push_back(-1);
    g.index.query_of_atom.push_back(a);
  }
  return g;
}

Lit pos(AtomId a) { return make_lit(a, false); }
Lit neg(AtomId a) { return make_lit(a, true); }

}  // namespace

TEST_CASE("forced atoms: unit propagation folds a chain, keeps blocks, same marginals and log Z",
          "[mln][forced_atoms]") {
  GroundNetwork net;
  net.add_atoms(7);
  net.add_hard_clause(std::vector<Lit>{pos(0)});           // x0 forced true
  net.add_hard_clause(std::vector<Lit>{neg(0), neg(1)});   // then x1 forced false
  net.add_hard_clause(std::vector<Lit>{pos(1), pos(2)});   // then x2 forced true
  net.add_clause(std::vector<Lit>{pos(1), pos(3)}, 1.3);   // x1 false: becomes (x3)
  net.add_clause(std::vector<Lit>{pos(2), neg(3)}, 0.7);   // x2 true: satisfied, to the constant
  net.add_clause(std::vector<Lit>{neg(3), pos(4)}, -0.4);
  net.add_exactly_one(std::vector<AtomId>{5, 6});
  net.add_hard_clause(std::vector<Lit>{pos(5)});           // a block atom: left to the block logic
  net.add_clause(std::vector<Lit>{pos(4), pos(6)}, 2.0);
  const auto before = exact_inference(net);

  auto g = identity_grounding(net);
  CHECK(fold_forced_atoms(g) == 3);
  CHECK(g.network.num_atoms() == 4);
  CHECK(g.network.num_blocks() == 1);
  CHECK(g.index.atom[0] == -1);
  CHECK(g.index.fixed[0] == 1);
  CHECK(g.index.fixed[1] == 0);
  CHECK(g.index.fixed[2] == 1);
  for (AtomId a = 0; a < g.network.num_atoms(); ++a) CHECK(g.index.atom[g.index.query_of_atom[a]] == a);
  const auto after = exact_inference(g.network);
  CHECK(after.log_z == Approx(before.log_z).epsilon(1e-12));
  for (std::int64_t q = 0; q < 7; ++q) {
    INFO("atom " << q);
    CHECK(g.marginal(after, q) == Approx(before.marginals[q]).margin(1e-12));
  }
  CHECK(fold_forced_atoms(g) == 0);  // nothing left to fold
}

TEST_CASE("forced atoms: a contradiction leaves the network for inference to report", "[mln][forced_atoms]") {
  GroundNetwork net;
  net.add_atoms(3);
  net.add_hard_clause(std::vector<Lit>{pos(0)});
  net.add_hard_clause(std::vector<Lit>{neg(0), pos(1)});
  net.add_hard_clause(std::vector<Lit>{neg(1)});
  net.add_clause(std::vector<Lit>{pos(2)}, 1.0);
  auto g = identity_grounding(net);
  CHECK(fold_forced_atoms(g) == 0);
  CHECK(g.network.num_atoms() == 3);
  CHECK(g.network.num_clauses() == 4);
  CHECK_THROWS_AS(exact_inference(g.network), MlnError);
}

TEST_CASE("forced atoms: a long implication chain (clauses in reverse order) is propagated to its end",
          "[mln][forced_atoms]") {
  // x0; x_{i} => x_{i+1}, listed from the end of the chain, so each pass over the clauses
  // fixes one more atom: past the first passes the queue over occurrences takes over.
  constexpr std::int32_t n = 12;
  GroundNetwork net;
  net.add_atoms(n + 1);
  for (std::int32_t i = n - 1; i >= 0; --i) net.add_hard_clause(std::vector<Lit>{neg(i), pos(i + 1)});
  net.add_hard_clause(std::vector<Lit>{pos(0)});
  net.add_clause(std::vector<Lit>{neg(n), pos(n - 3)}, 0.5);  // satisfied once the chain is fixed
  net.add_clause(std::vector<Lit>{neg(n)}, 0.8);              // never satisfied: dropped
  const auto before = exact_inference(net);
  auto g = identity_grounding(net);
  CHECK(fold_forced_atoms(g) == n + 1);
  CHECK(g.network.num_atoms() == 0);
  for (std::int64_t q = 0; q <= n; ++q) CHECK(g.index.fixed[q] == 1);
  CHECK(exact_inference(g.network).log_z == Approx(before.log_z).epsilon(1e-12));
}
