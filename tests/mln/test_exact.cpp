// Exact inference against an independent brute-force enumeration of the full ground MLN.
#include <catch2/catch.hpp>

#include <random>

#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"
#include "tests/mln/brute_force.h"
#include "tests/mln/random_kb.h"

using namespace ksmc::runtime::mln;
using ksmc::tests::mln::brute_force;

namespace {

struct SmokersKb {
  Program program;
  Domain domain;
  std::int32_t smokes = 0, cancer = 0, friends = 0;
  SmokersKb() {
    const auto person = program.add_type("person");
    smokes = program.add_predicate({"Smokes", {person}, true, true, -1});
    cancer = program.add_predicate({"Cancer", {person}, true, false, -1});
    friends = program.add_predicate({"Friends", {person, person}, false, false, -1});
    Clause c1;
    c1.name = "smoking_causes_cancer";
    c1.text = "Smokes(x) => Cancer(x)";
    c1.loc = {"smokers.ksm", 3};
    c1.variables = {{"x", person, false}};
    c1.literals = {{smokes, true, {Term::var(0)}}, {cancer, false, {Term::var(0)}}};
    c1.weight = 1.5;
    program.add_clause(c1);
    Clause c2;
    c2.name = "friends_smoke_alike";
    c2.text = "Friends(x, y) ^ Smokes(x) => Smokes(y)";
    c2.loc = {"smokers.ksm", 4};
    c2.variables = {{"x", person, false}, {"y", person, false}};
    c2.literals = {{friends, true, {Term::var(0), Term::var(1)}},
                   {smokes, true, {Term::var(0)}},
                   {smokes, false, {Term::var(1)}}};
    c2.weight = 1.1;
    program.add_clause(c2);
    domain.resize(1);
    for (const char* n : {"Anna", "Bob", "Chris", "Dan", "Edward"}) domain.add(person, n);
  }
};

}  // namespace

TEST_CASE("friends and smokers: exact equals brute force", "[mln][exact]") {
  SmokersKb kb;
  Evidence ev(kb.program, kb.domain);
  parse_db(
      "// classic example\n"
      "Friends(Anna, Bob)\nFriends(Bob, Anna)\nFriends(Anna, Edward)\nFriends(Edward, Anna)\n"
      "Friends(Chris, Dan)\nFriends(Dan, Chris)\nFriends(Bob, Chris)\n\n"
      "Smokes(Anna)\n!Smokes(Dan)\n",
      "smokers.db", kb.program, kb.domain, ev);
  const auto g = ground(kb.program, kb.domain, ev);
  CHECK(g.network.num_atoms() == 8);  // 3 free Smokes + 5 Cancer
  const auto exact = exact_inference(g.network);
  const auto ref = brute_force(kb.program, kb.domain, ev);
  REQUIRE(ref.feasible);
  CHECK(exact.log_z == Approx(ref.log_z).margin(1e-9));
  for (std::int32_t p : {kb.smokes, kb.cancer}) {
    for (std::int32_t c = 0; c < 5; ++c) {
      const std::int32_t args[] = {c};
      INFO(g.atom_name(g.query_index(p, args)));
      CHECK(std::abs(g.marginal(exact, p, args) - ref.at(p, c)) < 1e-9);
    }
  }
}

TEST_CASE("200 random knowledge bases: exact equals brute force", "[mln][exact][property]") {
  std::mt19937_64 rng(20240611);
  int feasible = 0, infeasible = 0, with_blocks = 0;
  for (int trial = 0; trial < 200; ++trial) {
    auto kb = ksmc::tests::mln::make_random_kb(rng);
    INFO("trial " << trial);
    const auto ref = brute_force(kb.program, kb.domain, *kb.evidence);
    if (!ref.feasible) {
      // The runtime must refuse too: either at grounding (folded evidence) or in the engine.
      CHECK_THROWS_AS(exact_inference(ground(kb.program, kb.domain, *kb.evidence).network), MlnError);
      ++infeasible;
      continue;
    }
    ++feasible;
    const auto g = ground(kb.program, kb.domain, *kb.evidence);
    if (g.network.num_blocks() > 0) ++with_blocks;
    const auto exact = exact_inference(g.network);
    CHECK(std::abs(exact.log_z - ref.log_z) < 1e-9);
    for (std::int64_t q = 0; q < g.index.num_query_atoms; ++q) {
      // map query index back to (predicate, flat)
      std::int32_t p = 0;
      for (std::size_t i = 0; i < g.index.offset.size(); ++i)
        if (g.index.offset[i] >= 0 && g.index.offset[i] <= q) p = static_cast<std::int32_t>(i);
      const auto flat = q - g.index.offset[p];
      INFO(g.atom_name(q));
      CHECK(std::abs(g.marginal(exact, q) - ref.at(p, flat)) < 1e-9);
    }
  }
  CHECK(feasible >= 100);
  CHECK(with_blocks >= 5);
  WARN("random KBs: " << feasible << " feasible (" << with_blocks << " with blocks), " << infeasible
                      << " unsatisfiable, all matched brute force");
}

TEST_CASE("exact refuses a too-large component with a clear message", "[mln][exact]") {
  GroundNetwork net;
  net.set_label_names({"chain"});
  net.add_atoms(30, 0);
  for (AtomId a = 0; a + 1 < 30; ++a) {
    const Lit lits[] = {make_lit(a, true), make_lit(a + 1, false)};
    net.add_clause(lits, 0.5);
  }
  ExactOptions opt;
  opt.max_component_bits = 24;
  opt.use_elimination = false;
  try {
    exact_inference(net, opt);
    FAIL("expected MlnError");
  } catch (const MlnError& e) {
    CHECK(std::string(e.what()) ==
          "exact inference: a connected component has 30 free atoms (30 bits of state), above the limit of 24 bits "
          "(network: 30 atoms, 29 clauses); its atoms come from chain; neither enumeration nor variable "
          "elimination fits the limits; use the auto or mcsat method, or raise max_component_bits");
  }
}

TEST_CASE("exact: closed-form single atoms and blocks", "[mln][exact]") {
  GroundNetwork net;
  const auto a = net.add_atom();
  const auto b0 = net.add_atom(), b1 = net.add_atom(), b2 = net.add_atom();
  const Lit la[] = {make_lit(a, false)};
  net.add_clause(la, 2.0);
  const AtomId blk[] = {b0, b1, b2};
  net.add_exactly_one(blk);
  const Lit lb[] = {make_lit(b1, false)};
  net.add_clause(lb, std::log(2.0));
  net.add_constant(0.25);
  const auto r = exact_inference(net);
  CHECK(r.marginals[a] == Approx(std::exp(2.0) / (1 + std::exp(2.0))).epsilon(1e-12));
  CHECK(r.marginals[b1] == Approx(0.5).epsilon(1e-12));
  CHECK(r.marginals[b0] == Approx(0.25).epsilon(1e-12));
  CHECK(r.log_z == Approx(0.25 + std::log(1 + std::exp(2.0)) + std::log(4.0)).epsilon(1e-12));
}
