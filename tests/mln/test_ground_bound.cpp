// Bounded grounding (runtime/mln/ground_bound.h) and cancellation of the Markov logic loops
// (runtime/io/cancel.h polled by the grounder and the engines).
#include <catch2/catch.hpp>

#include <string>

#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"
#include "runtime/mln/ground_bound.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/mcsat.h"

using namespace ksmc::runtime::mln;
namespace io = ksmc::runtime::io;

namespace {

// node type with `n` constants; evidence e(node, node); query r(node, node); one soft rule
// `!e(x1, x2) v r(x1, x2) v ... v r(x_{k-1}, x_k)` chaining k variables.
struct Chain {
  Program program;
  Domain domain;
  std::int32_t e = 0;
  Chain(int k, int n) {
    const auto node = program.add_type("node");
    e = program.add_predicate(Predicate{"e", {node, node}, false});
    const auto r = program.add_predicate(Predicate{"r", {node, node}, true});
    Clause c;
    c.name = "chain";
    c.text = "chain of " + std::to_string(k);
    c.weight = 1.0;
    for (int v = 0; v < k; ++v) c.variables.push_back(Variable{"x" + std::to_string(v + 1), node, false});
    c.literals.push_back(Literal{e, true, {Term::var(0), Term::var(1)}});
    for (int v = 0; v + 1 < k; ++v) c.literals.push_back(Literal{r, false, {Term::var(v), Term::var(v + 1)}});
    program.add_clause(c);
    domain.resize(program.types.size());
    for (int i = 0; i < n; ++i) domain.add(node, "C" + std::to_string(i));
  }
};

// Every e(x, y) true: the evidence literal `!e(x1, x2)` folds nothing away.
void all_true(const Chain& ch, Evidence& ev) {
  for (std::int32_t a = 0; a < ch.domain.size(0); ++a)
    for (std::int32_t b = 0; b < ch.domain.size(0); ++b) {
      const std::int32_t args[] = {a, b};
      ev.set(ch.e, args, true);
    }
}

struct LimitGuard {
  ~LimitGuard() { set_max_ground_clauses(kDefaultMaxGroundClauses); }
};

}  // namespace

TEST_CASE("ground bound: binding size, refined by closed-world evidence", "[mln][bound]") {
  Chain ch(4, 8);
  Evidence ev(ch.program, ch.domain);
  auto est = estimate_ground_clauses(ch.program, ch.domain, ev, ch.program.clauses[0]);
  CHECK(est.bindings == 4096.0);
  CHECK(est.clauses == 0.0);  // no e(x, y) is true: `!e(x1, x2)` satisfies every grounding
  CHECK(est.binding == "x1:node(8) x x2:node(8) x x3:node(8) x x4:node(8)");
  const std::int32_t ab[] = {0, 1}, ba[] = {1, 0};
  ev.set(ch.e, ab, true);
  ev.set(ch.e, ba, true);
  est = estimate_ground_clauses(ch.program, ch.domain, ev, ch.program.clauses[0]);
  CHECK(est.clauses == 2.0 * 64.0);  // 2 true e atoms x 8 x 8 for x3, x4
}

TEST_CASE("ground bound: a 17-variable chain over 8 constants is refused before grounding", "[mln][bound]") {
  Chain ch(17, 8);
  Evidence ev(ch.program, ch.domain);
  all_true(ch, ev);
  try {
    (void)ground(ch.program, ch.domain, ev);
    FAIL("no refusal");
  } catch (const MlnError& e) {
    const std::string m = e.what();
    CHECK(m.find("rule chain `chain of 17`") != std::string::npos);
    CHECK(m.find("would ground to up to 2.25e+15 clauses") != std::string::npos);
    CHECK(m.find("x17:node(8) = 2.25e+15 groundings") != std::string::npos);
    CHECK(m.find("above the limit of 50,000,000; raise it with --max-ground-clauses N") != std::string::npos);
  }
  LimitGuard restore;
  Chain small(3, 8);
  Evidence sev(small.program, small.domain);
  for (std::int32_t b = 0; b < 8; ++b) {
    const std::int32_t args[] = {0, b};
    sev.set(small.e, args, true);
  }
  set_max_ground_clauses(63);  // estimate 8 x 8 = 64
  CHECK_THROWS_WITH(ground(small.program, small.domain, sev), Catch::Contains("above the limit of 63"));
  set_max_ground_clauses(64);
  CHECK(ground(small.program, small.domain, sev).network.num_clauses() > 0);
}

TEST_CASE("cancellation: grounding and MC-SAT stop at a request; a CancelShield lets them run", "[mln][cancel]") {
  Chain ch(3, 8);
  Evidence ev(ch.program, ch.domain);
  all_true(ch, ev);
  const Grounding g = ground(ch.program, ch.domain, ev);
  io::request_cancel(15);
  CHECK_THROWS_AS(mc_sat(g.network, McSatOptions{}), io::Cancelled);
  {
    const io::CancelShield shield;
    CHECK(mc_sat(g.network, McSatOptions{}).samples > 0);
  }
  io::clear_cancel();
  CHECK(mc_sat(g.network, McSatOptions{}).samples > 0);
}
