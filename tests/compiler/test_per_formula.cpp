// Per-formula weight semantics (compiler/lower/per_formula.h) against the default split
// semantics, on `w 2: A(x) => B(x) ^ C(x).` (two CNF clauses) over one constant: the
// closed forms over the 8 worlds of A, B, C differ, and each mode gives its own.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "compiler/lower/per_formula.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"
#include "tests/compiler/lower_fixture.h"

using ksmc::tests::lower_text;
namespace mln = ksmc::runtime::mln;

namespace {

const char* kSource =
    "domain pf;\n"
    "type person;\n"
    "query A(person), B(person), C(person);\n"
    "w 2: A(x) => B(x) ^ C(x).\n";

struct Marginals {
  double a = 0.0, b = 0.0, log_z = 0.0;
};

Marginals infer(const ksmc::compiler::lower::MlnIr& ir) {
  const auto& program = ir.program;
  mln::Domain domain;
  domain.resize(static_cast<std::int32_t>(program.types.size()));
  domain.add(*program.find_type("person"), "Anna");
  mln::Evidence evidence(program, domain);
  const auto g = mln::ground(program, domain, evidence);
  const auto r = mln::exact_inference(g.network);
  const std::int32_t anna[] = {0};
  return {g.marginal(r, *program.find_predicate("A"), anna), g.marginal(r, *program.find_predicate("B"), anna),
          r.log_z};
}

}  // namespace

TEST_CASE("per-formula weights: the weight counts once when the whole formula holds", "[lower][per_formula]") {
  const double e = std::exp(1.0), e2 = std::exp(2.0);
  auto split = lower_text(kSource);
  INFO(split.diagnostics);
  REQUIRE(split.ok);
  REQUIRE(split.ir.program.clauses.size() == 2);
  // Split: clauses (!A v B) and (!A v C), weight 1 each. A false: 4 worlds of e^2; A true:
  // e^2 (B, C), e (one of them) twice, 1 (neither).
  const auto s = infer(split.ir);
  CHECK(s.log_z == Approx(std::log(5 * e2 + 2 * e + 1)).epsilon(1e-12));
  CHECK(s.a == Approx((e2 + 2 * e + 1) / (5 * e2 + 2 * e + 1)).epsilon(1e-12));

  auto whole = lower_text(kSource);
  REQUIRE(whole.ok);
  REQUIRE(ksmc::compiler::lower::use_per_formula_weights(whole.ir).empty());
  // holds[F] with 2 hard clauses !holds v C_i, 2 x 2 literal choices, one soft clause.
  CHECK(whole.ir.program.clauses.size() == 2 + 4 + 1);
  REQUIRE(whole.ir.rules.size() == 1);
  REQUIRE(whole.ir.rules[0].clauses.size() == 1);
  CHECK(whole.ir.program.clauses[static_cast<std::size_t>(whole.ir.rules[0].clauses[0])].weight == 2.0);
  CHECK(whole.ir.program.predicates.back().auxiliary);
  // Per formula: F is false in 3 worlds (A true, not both B and C): Z = 5 e^2 + 3.
  const auto w = infer(whole.ir);
  CHECK(w.log_z == Approx(std::log(5 * e2 + 3)).epsilon(1e-12));
  CHECK(w.a == Approx((e2 + 3) / (5 * e2 + 3)).epsilon(1e-12));
  CHECK(w.b == Approx((3 * e2 + 1) / (5 * e2 + 3)).epsilon(1e-12));
  CHECK(std::abs(w.a - s.a) > 0.05);  // 0.260 against 0.319
}

TEST_CASE("per-formula weights: one-clause formulas unchanged, exists refused", "[lower][per_formula]") {
  auto one = lower_text(
      "domain pf;\ntype person;\nquery A(person), B(person), C(person);\nw 2: A(x) => B(x) v C(x).\n");
  INFO(one.diagnostics);
  REQUIRE(one.ok);
  const auto before = one.ir.program.clauses.size();
  REQUIRE(ksmc::compiler::lower::use_per_formula_weights(one.ir).empty());
  CHECK(one.ir.program.clauses.size() == before);
  CHECK(one.ir.program.clauses[0].weight == 2.0);

  auto ex = lower_text(std::string(kSource) + "w 1: A(x) => (exists y: B(y)) ^ C(x).\n");
  INFO(ex.diagnostics);
  REQUIRE(ex.ok);
  const auto error = ksmc::compiler::lower::use_per_formula_weights(ex.ir);
  CHECK(error.find("test.ksm:5: error: rule") == 0);
  CHECK(error.find("without `exists`") != std::string::npos);
}
