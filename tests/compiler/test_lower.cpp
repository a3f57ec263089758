#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "compiler/lower/dump_ir.h"
#include "tests/compiler/lower_fixture.h"

using ksmc::tests::lower_text;

namespace {

const char* kHeader =
    "domain t;\n"
    "type thing;\n"
    "type colour = {Red, Green};\n"
    "evidence e(thing), r(thing, thing);\n"
    "query a(thing), b(thing), c(thing), k(thing, colour);\n";

std::string dump(const ksmc::compiler::lower::MlnIr& ir) {
  std::ostringstream ss;
  ksmc::compiler::lower::dump_ir(ir, ss);
  return ss.str();
}

}  // namespace

TEST_CASE("prob weights become log-odds and a conjunction in the head splits the weight") {
  auto l = lower_text(std::string(kHeader) + "prob 0.8: e(x) => a(x) ^ b(x).\nhard a(x) => !c(x).\nw -1.5: c(x) v k(x, Red).\n");
  INFO(l.diagnostics);
  REQUIRE(l.ok);
  const auto& p = l.ir.program;
  REQUIRE(p.clauses.size() == 4);
  const double w = std::log(0.8 / 0.2);
  CHECK(p.clauses[0].weight == Approx(w / 2));
  CHECK(p.clauses[1].weight == Approx(w / 2));
  CHECK(p.clauses[0].name == "a_b_8341_c1");
  CHECK(p.clauses[1].name == "a_b_8341_c2");
  CHECK(p.clauses[2].hard);
  CHECK(p.clauses[2].name == "c_517d");
  CHECK(p.clauses[3].weight == -1.5);
  // The constant Red stays a constant; x is a variable of type thing.
  const auto& lit = p.clauses[3].literals[1];
  CHECK_FALSE(lit.args[1].is_variable);
  CHECK(lit.args[1].constant == "Red");
  CHECK(dump(l.ir).find("clause a_b_8341_c1 w=0.6931471805599454: !e(x) v a(x)") != std::string::npos);
}

TEST_CASE("equivalence gives two clauses; its negation two others") {
  auto l = lower_text(std::string(kHeader) + "hard a(x) <=> b(x).\nhard !(a(x) <=> c(x)).\n");
  INFO(l.diagnostics);
  REQUIRE(l.ok);
  const std::string d = dump(l.ir);
  INFO(d);
  CHECK(d.find("clause b_ab6f_c1 hard: !a(x) v b(x)") != std::string::npos);
  CHECK(d.find("clause b_ab6f_c2 hard: a(x) v !b(x)") != std::string::npos);
  CHECK(d.find(": a(x) v c(x)") != std::string::npos);
  CHECK(d.find(": !a(x) v !c(x)") != std::string::npos);
}

TEST_CASE("a positive existential stays in its clause; a negated one becomes universal") {
  auto l = lower_text(std::string(kHeader) + "hard a(x) => exists y: r(x, y) v b(y).\nhard (exists y: r(x, y)) => c(x).\n");
  INFO(l.diagnostics);
  REQUIRE(l.ok);
  const std::string d = dump(l.ir);
  INFO(d);
  CHECK(d.find("hard: exists y: !a(x) v r(x, y) v b(y)") != std::string::npos);
  CHECK(d.find("hard: !r(x, y) v c(x)") != std::string::npos);
  const auto& c1 = l.ir.program.clauses[1];
  for (const auto& v : c1.variables) CHECK_FALSE(v.existential);
}

TEST_CASE("an existential over a conjunction is reported at the quantifier") {
  auto l = lower_text(std::string(kHeader) + "hard a(x) => exists y: r(x, y) ^ b(y).\n");
  CHECK_FALSE(l.ok);
  CHECK(l.diagnostics.find("test.ksm:6:") != std::string::npos);
  CHECK(l.diagnostics.find("ranges over a conjunction") != std::string::npos);
}

TEST_CASE("exactly one of becomes a group; an exclusive argument is kept on the predicate") {
  auto l = lower_text(
      "domain t;\ntype u;\ntype kind = {K1, K2};\nevidence e(u);\nquery p(u), q(u), s(u, kind!);\n"
      "hard exactly one of p(x), q(x).\nprob 0.9: e(x) => p(x).\nprob 0.6: e(x) => s(x, K1).\nprob 0.6: p(x) => q(x).\n");
  INFO(l.diagnostics);
  REQUIRE(l.ok);
  REQUIRE(l.ir.program.groups.size() == 1);
  CHECK(l.ir.program.groups[0].predicates.size() == 2);
  CHECK(l.ir.program.predicates[3].exclusive_arg == 1);
  CHECK(l.ir.enumerated[1] == std::vector<std::string>{"K1", "K2"});
  CHECK(l.ir.rules[0].group == 0);
  CHECK(l.ir.rules[0].clauses.empty());
}

TEST_CASE("lowering is deterministic") {
  const std::string text = std::string(kHeader) + "prob 0.7: e(x) ^ r(x, y) => a(y) v b(x).\nhard !r(x, x).\n";
  auto l1 = lower_text(text);
  auto l2 = lower_text(text);
  REQUIRE(l1.ok);
  CHECK(dump(l1.ir) == dump(l2.ir));
}

TEST_CASE("rule names come from @name or from the content, not from the position") {
  const std::string body = "prob 0.7: e(x) => a(x).\n@no_c hard a(x) => !c(x).\n";
  auto l1 = lower_text(std::string(kHeader) + body);
  REQUIRE(l1.ok);
  REQUIRE(l1.ir.rules.size() == 2);
  CHECK(l1.ir.rules[1].name == "no_c");
  const std::string first = l1.ir.rules[0].name;
  CHECK(first.rfind("a_", 0) == 0);
  CHECK(first.size() == std::string("a_").size() + 4);
  // A weight edit, another layout and an inserted rule before it keep the name.
  auto l2 = lower_text(std::string(kHeader) + "w 2: e(x) => b(x).\nprob   0.75:  e(x)=>a(x).\n@no_c hard a(x) => !c(x).\n");
  REQUIRE(l2.ok);
  CHECK(l2.ir.rules[1].name == first);
  CHECK(l2.ir.rules[2].name == "no_c");
  // Another formula over the same predicates gets another hash.
  auto l3 = lower_text(std::string(kHeader) + "prob 0.7: !e(x) => a(x).\n");
  REQUIRE(l3.ok);
  CHECK(l3.ir.rules[0].name != first);
}

TEST_CASE("a duplicate rule name is an error at the second rule") {
  auto l = lower_text(std::string(kHeader) + "@same prob 0.7: e(x) => a(x).\n@same hard a(x) => !c(x).\n");
  CHECK_FALSE(l.ok);
  CHECK(l.diagnostics.find("test.ksm:7:2: error: duplicate rule name 'same'") != std::string::npos);
  auto m = lower_text(std::string(kHeader) + "prob 0.7: e(x) => a(x).\nprob 0.8: e(x) => a(x).\n");
  CHECK_FALSE(m.ok);
  CHECK(m.diagnostics.find("name one with '@name'") != std::string::npos);
}

TEST_CASE("two different formulas whose short names collide both take the 8-digit hash") {
  // FNV-1a of "a(v149)" and of "a(v276)" fold to the same 16 bits (9d86).
  auto l = lower_text(std::string(kHeader) + "w 1: a(v149).\nw 1: a(v276).\nw 1: a(v3).\n");
  INFO(l.diagnostics);
  REQUIRE(l.ok);
  REQUIRE(l.ir.rules.size() == 3);
  CHECK(l.ir.rules[0].name == "a_c37b5efd");
  CHECK(l.ir.rules[1].name == "a_5a5ac7dc");
  CHECK(l.ir.rules[2].name.size() == std::string("a_").size() + 4);  // no collision: short
}
