// The contract with generated grounding code: code written the way compiler/emit
// writes it (loops over constants, FactorContext calls) must produce exactly the
// network of the generic grounder. Five table-top rules cover the cases: an
// evidence-only hard rule, hard/soft rules mixing evidence and query atoms, and
// two-variable rules.
#include <catch2/catch.hpp>

#include "runtime/mln/error.h"
#include "runtime/mln/factor_context.h"
#include "runtime/mln/grounder.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;

namespace {

// Keeps rules r4, r7, r10 (both halves), r13, r14 of the table-top KB, in order.
Program subset(const ksmc::tests::mln::TabletopKb& kb) {
  Program p = kb.program;
  std::vector<Clause> keep;
  for (const auto& c : kb.program.clauses)
    if (c.name == "r4" || c.name == "r7" || c.name == "r10" || c.name == "r13" || c.name == "r14") keep.push_back(c);
  p.clauses = keep;
  return p;
}

// Hand-written in the style of generated code for the five rules above.
Grounding ground_like_generated(const Program& program, const ksmc::tests::mln::TabletopKb& kb, const Domain& domain,
                                const Evidence& evidence) {
  Grounding g = prepare_grounding(program, domain, evidence);
  FactorContext f(g, evidence);
  const std::int32_t n = f.size(kb.object);
  const double w09 = std::log(0.9 / 0.1);
  for (std::int32_t a = 0; a < n; ++a) {
    for (std::int32_t b = 0; b < n; ++b) {  // r4: contact(a, b) => contact(b, a)
      f.begin();
      if (!f.ev(kb.contact, a * n + b) || f.ev(kb.contact, b * n + a)) continue;
      f.hard(0, {a, b});
    }
  }
  for (std::int32_t o = 0; o < n; ++o) {  // r7: table(o) => !falseEst(o)
    f.begin();
    if (!f.ev(kb.table, o) || f.query(kb.false_est, o, true)) continue;
    f.hard(1, {o});
  }
  auto body = [&](std::int32_t a, std::int32_t b) {
    return f.ev(kb.stable, a) && f.ev(kb.stable, b) && f.ev(kb.contact, a * n + b) && f.ev(kb.higher, a * n + b);
  };
  for (std::int32_t a = 0; a < n; ++a) {  // r10 (first half): ... => supportive(b)
    for (std::int32_t b = 0; b < n; ++b) {
      f.begin();
      if (body(a, b) && !f.query(kb.supportive, b, false)) f.hard(2, {a, b});
    }
  }
  for (std::int32_t a = 0; a < n; ++a) {  // r10 (second half): ... => supported(a)
    for (std::int32_t b = 0; b < n; ++b) {
      f.begin();
      if (body(a, b) && !f.query(kb.supported, a, false)) f.hard(3, {a, b});
    }
  }
  for (std::int32_t o = 0; o < n; ++o) {  // r13: hover(o) => falseEst(o) v hidden(o)
    f.begin();
    if (!f.ev(kb.hover, o) || f.query(kb.false_est, o, false) || f.query(kb.hidden, o, false)) {
      f.satisfied(w09);
      continue;
    }
    f.soft(w09, 4);
  }
  for (std::int32_t a = 0; a < n; ++a) {  // r14: intersect(a, b) => falseEst(a) v falseEst(b)
    for (std::int32_t b = 0; b < n; ++b) {
      f.begin();
      if (!f.ev(kb.intersect, a * n + b) || f.query(kb.false_est, a, false) || f.query(kb.false_est, b, false)) {
        f.satisfied(w09);
        continue;
      }
      f.soft(w09, 5);
    }
  }
  fold_forced_atoms(g);  // as generated code ends
  return g;
}

}  // namespace

TEST_CASE("FactorContext-based grounding equals the generic grounder", "[mln][factor_context]") {
  ksmc::tests::mln::TabletopKb kb;
  const Program program = subset(kb);
  REQUIRE(program.clauses.size() == 6);
  for (const char* name : {"scene7.db", "scene20.db"}) {
    INFO(name);
    const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/" + name;
    const auto text = read_text_file(path);
    Domain d;
    collect_db_constants(text, path, program, d);
    Evidence ev(program, d);
    parse_db(text, path, program, d, ev);
    const auto generic = ground(program, d, ev);
    const auto generated = ground_like_generated(program, kb, d, ev);
    const auto& a = generic.network;
    const auto& b = generated.network;
    REQUIRE(a.num_atoms() == b.num_atoms());
    REQUIRE(a.num_clauses() == b.num_clauses());
    CHECK(a.num_blocks() == b.num_blocks());
    CHECK(a.constant() == Approx(b.constant()).epsilon(1e-12));
    for (std::int32_t c = 0; c < a.num_clauses(); ++c) {
      CHECK(std::vector<Lit>(a.clause(c).begin(), a.clause(c).end()) ==
            std::vector<Lit>(b.clause(c).begin(), b.clause(c).end()));
      CHECK(a.weight(c) == b.weight(c));
      CHECK(a.origin(c) == b.origin(c));
    }
  }
}

TEST_CASE("FactorContext names the rule and binding of an unsatisfiable hard grounding", "[mln][factor_context]") {
  ksmc::tests::mln::TabletopKb kb;
  const Program program = subset(kb);
  Domain d(1);
  for (auto o : {"Table", "A", "B"}) d.add(kb.object, o);
  Evidence ev(program, d);
  parse_db("contact(A, B)\n", "s.db", program, d, ev);
  CHECK_THROWS_WITH(ground_like_generated(program, kb, d, ev),
                    "hard rule r4 `contact(o1, o2) => contact(o2, o1)` (tabletop.ksm:13) is unsatisfiable under the "
                    "evidence for o1=A, o2=B");
}
