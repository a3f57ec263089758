// runtime/domain Semantics on the toy domain (toy_binding.h): evidence from extractors
// (self-pairs false without a call), the evidence-keyed cache, update == evaluate,
// conditional priors, impossible evidence, log Z / log MAP against the engines, and the
// queries JSON / evidence .db round trip through mln::parse_db.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "runtime/domain/labels.h"
#include "runtime/domain/semantics.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/inference.h"
#include "tests/domain/toy_binding.h"

namespace dom = ksmc::runtime::domain;
namespace mln = ksmc::runtime::mln;
using ksmc::tests::domain::ToyScene;
using ksmc::tests::domain::toy_binding;
using ksmc::tests::domain::toy_ids;

namespace {

const std::vector<std::string> kNames3{"i0", "i1", "i2"};

void require_same_values(const dom::Outcome& a, const dom::Outcome& b) {
  REQUIRE(a.values.size() == b.values.size());
  for (std::size_t p = 0; p < a.values.size(); ++p) {
    INFO("predicate " << p);
    REQUIRE(a.values[p].size() == b.values[p].size());
    for (std::size_t k = 0; k < a.values[p].size(); ++k) CHECK(a.values[p][k] == Approx(b.values[p][k]).margin(1e-12));
  }
}

// Three items: 0 and 1 near each other, 2 big.
struct Toy {
  const dom::SemanticBinding<ToyScene> binding = toy_binding();
  const ksmc::tests::domain::ToyIds& id = toy_ids();
  dom::Semantics<ToyScene> sem{binding};
  const ToyScene s{{0.0, 0.5, 6.0}};
  const std::shared_ptr<const dom::Outcome> o = sem.evaluate(s, 3);
};

}  // namespace

TEST_CASE_METHOD(Toy, "semantics: evidence from the extractors, self-pairs false, enumerated constants", "[domain][semantics]") {
  REQUIRE(o->possible);
  CHECK(o->constants == 3);
  // near: (0,1) and (1,0) only; (a, a) is false although |x - x| < 1.
  const std::vector<double> near{0, 1, 0, 1, 0, 0, 0, 0, 0};
  CHECK(o->values[static_cast<std::size_t>(id.near)] == near);
  CHECK(o->values[static_cast<std::size_t>(id.big)] == std::vector<double>{0, 0, 1});
  // 3 x 2 ordered pairs + 3 unary atoms: no call for (a, a).
  CHECK(sem.core().stats().extractor_calls == 9);
  // Paint(item, color) spans the 3 items x 2 enumerated colours.
  CHECK(o->values[static_cast<std::size_t>(id.paint)].size() == 6);
  const std::array<std::int32_t, 2> red{1, 0};
  CHECK(sem.value(*o, id.paint, red) == Approx(0.6).margin(1e-9));
  const std::array<std::int32_t, 1> tall2{2};
  CHECK(sem.value(*o, id.tall, tall2) > 0.85);
  const std::array<std::int32_t, 2> p01{0, 1}, p02{0, 2};
  CHECK(sem.value(*o, id.pair, p01) > 0.75);
  CHECK(sem.value(*o, id.pair, p02) == Approx(0.5).margin(1e-9));  // no rule moves it
  CHECK(sem.core().enumerated() == 0);
  CHECK(sem.core().constants_of(id.color, 3) == 2);
}

TEST_CASE("semantics: the cache recalls equal evidence; another scene with the same bits is a hit", "[domain][semantics]") {
  const auto binding = toy_binding();
  dom::Semantics<ToyScene> sem(binding);
  const auto a = sem.evaluate(ToyScene{{0.0, 0.5, 6.0}}, 3);
  const auto b = sem.evaluate(ToyScene{{0.0, 0.5, 6.0}}, 3);
  const auto c = sem.evaluate(ToyScene{{0.1, 0.4, 7.0}}, 3);  // same relations
  CHECK(a == b);
  CHECK(a == c);
  CHECK(sem.core().stats().evaluations == 3);
  CHECK(sem.core().stats().cache_hits == 2);
  CHECK(sem.core().stats().inferences == 1);
  const auto d = sem.evaluate(ToyScene{{0.0, 3.0, 6.0}}, 3);  // (0,1) no longer near
  CHECK(d != a);
  CHECK(sem.core().stats().inferences == 2);
  const auto e = sem.evaluate(ToyScene{{0.0, 0.5}}, 2);  // fewer constants: another key
  CHECK(e->constants == 2);
  CHECK(sem.core().stats().inferences == 3);
}

TEST_CASE("semantics: update re-evaluates only atoms of changed constants and equals evaluate", "[domain][semantics]") {
  const auto binding = toy_binding();
  dom::Semantics<ToyScene> sem(binding);
  dom::Semantics<ToyScene> fresh(binding);
  ToyScene s{{0.0, 0.5, 6.0, 9.0}};
  const auto base = sem.evaluate(s, 4);
  const auto calls0 = sem.core().stats().extractor_calls;
  CHECK(calls0 == 4 * 3 + 4);

  SECTION("relative to a base outcome, after a rejected proposal") {
    ToyScene rejected = s;
    rejected.x[3] = 6.5;  // near 2, both big: impossible
    const std::array<std::int32_t, 1> three{3};
    const auto r = sem.update(rejected, 4, three, *base);
    CHECK_FALSE(r->possible);
    CHECK(std::isinf(r->log_z));
    // The proposal is rejected; the next one moves constant 1 from the current state.
    ToyScene next = s;
    next.x[1] = 3.0;  // no longer near 0
    const std::array<std::int32_t, 1> one{1};
    const auto before = sem.core().stats().extractor_calls;
    const auto u = sem.update(next, 4, one, *base);
    // Atoms with argument 1: 3 + 3 ordered pairs and one unary atom.
    CHECK(sem.core().stats().extractor_calls - before == 7);
    require_same_values(*u, *fresh.evaluate(next, 4));
  }
  SECTION("relative to the previous call") {
    ToyScene next = s;
    next.x[0] = 9.5;  // near 3 (and big: both big, so impossible)
    const std::array<std::int32_t, 1> zero{0};
    const auto u = sem.update(next, 4, zero);
    require_same_values(*u, *fresh.evaluate(next, 4));
    CHECK_FALSE(u->possible);
    next.x[3] = 20.0;
    const std::array<std::int32_t, 1> three{3};
    const auto v = sem.update(next, 4, three);
    CHECK(v->possible);
    require_same_values(*v, *fresh.evaluate(next, 4));
  }
  SECTION("several changed constants: each touched atom evaluated once") {
    ToyScene next = s;
    next.x[1] = 8.7;  // near 3 now, not 0
    next.x[3] = 30.0;
    const std::array<std::int32_t, 2> three_one{3, 1};  // any order
    const auto before = sem.core().stats().extractor_calls;
    const auto u = sem.update(next, 4, three_one, *base);
    // Ordered pairs with 1 or 3 in them: 12 less (0, 2) and (2, 0); unary atoms of 1 and 3.
    CHECK(sem.core().stats().extractor_calls - before == 10 + 2);
    require_same_values(*u, *fresh.evaluate(next, 4));
  }
  SECTION("another n evaluates every atom") {
    ToyScene more = s;
    more.x.push_back(0.2);
    const std::array<std::int32_t, 1> four{4};
    const auto u = sem.update(more, 5, four);
    CHECK(sem.core().stats().extractor_calls - calls0 == 5 * 4 + 5);
    require_same_values(*u, *fresh.evaluate(more, 5));
  }
}

TEST_CASE_METHOD(Toy, "semantics: conditional priors sum the terms of the bindings whose conditions hold", "[domain][semantics]") {
  double expect = 0.0;
  for (std::int32_t a = 0; a < 3; ++a) {
    const std::array<std::int32_t, 1> u{a};
    if (sem.value(*o, id.big, u) < 0.5) expect -= 1.0;
    for (std::int32_t b = 0; b < 3; ++b) {
      const std::array<std::int32_t, 2> ab{a, b};
      if (sem.value(*o, id.pair, ab) > 0.5) expect -= (s.x[static_cast<std::size_t>(a)] - s.x[static_cast<std::size_t>(b)]) *
                                                       (s.x[static_cast<std::size_t>(a)] - s.x[static_cast<std::size_t>(b)]);
    }
  }
  // Pair(0,1) and Pair(1,0) hold (0.25 each), items 0 and 1 are not big.
  CHECK(expect == Approx(-2.5));
  CHECK(sem.conditional_priors(s, *o) == Approx(expect));
  // Impossible evidence: no term.
  const ToyScene bad{{6.0, 6.5}};
  const auto ob = sem.evaluate(bad, 2);
  REQUIRE_FALSE(ob->possible);
  CHECK(sem.conditional_priors(bad, *ob) == 0.0);
}

TEST_CASE("semantics: log Z and log MAP agree with the engines; empty evidence", "[domain][semantics]") {
  const auto binding = toy_binding();
  dom::SemanticOptions opt;
  opt.log_z = true;
  opt.log_map = true;
  dom::Semantics<ToyScene> sem(binding, opt);
  const ToyScene s{{0.0, 0.5, 6.0}};
  const auto o = sem.evaluate(s, 3);
  // The same evidence by hand.
  const auto& p = ksmc::tests::domain::toy_program();
  mln::Domain d = ksmc::tests::domain::toy_make_domain();
  for (const char* c : {"a", "b", "c"}) d.add(toy_ids().item, c);
  mln::Evidence ev(p, d);
  const std::array<std::int32_t, 2> p01{0, 1}, p10{1, 0};
  for (std::int64_t k = 0; k < ev.num_atoms(toy_ids().near); ++k) ev.set_flat(toy_ids().near, k, 0);
  ev.set(toy_ids().near, p01, true);
  ev.set(toy_ids().near, p10, true);
  for (std::int32_t a = 0; a < 3; ++a) {
    const std::array<std::int32_t, 1> u{a};
    ev.set(toy_ids().big, u, a == 2);
  }
  const mln::Grounding g = mln::ground(p, d, ev);
  const mln::InferenceResult r = mln::exact_inference(g.network);
  CHECK(o->log_z == Approx(r.log_z).epsilon(1e-12));
  CHECK(o->log_map == Approx(mln::exact_map(g.network).log_weight).epsilon(1e-12));
  CHECK(o->exact);
  CHECK(o->log_map <= o->log_z);
  // No relation holds: the baseline of `prior mln`-style terms.
  const auto e = sem.empty_evidence(3);
  CHECK(e->values[static_cast<std::size_t>(toy_ids().near)] == std::vector<double>(9, 0.0));
  CHECK(e->log_z != o->log_z);
  CHECK(sem.empty_evidence(3) == e);
  // empty_evidence does not disturb update's previous-call bits.
  const std::array<std::int32_t, 1> none{0};
  require_same_values(*sem.update(s, 3, none), *o);
  // No constant: no atom over items, but Paint has none either; nothing to infer.
  const auto z = sem.evaluate(ToyScene{}, 0);
  CHECK(z->method == "none");
  CHECK(z->log_z == 0.0);
}

TEST_CASE_METHOD(Toy, "semantics: queries JSON and evidence .db round trip", "[domain][semantics]") {
  const auto q = sem.queries_json(*o, kNames3);
  // Every query predicate in program order, every atom in constant order.
  std::vector<std::string> preds;
  for (const auto& [k, v] : q.items()) preds.push_back(k);
  CHECK(preds == std::vector<std::string>{"Pair", "Tall", "Short", "Paint"});
  std::vector<std::string> keys;
  for (const auto& [k, v] : q["Paint"].items()) keys.push_back(k);
  CHECK(keys == std::vector<std::string>{"i0,red", "i0,green", "i1,red", "i1,green", "i2,red", "i2,green"});
  CHECK(q["Pair"].size() == 9);
  const std::array<std::int32_t, 2> p01{0, 1};
  CHECK(q["Pair"]["i0,i1"].get<double>() == Approx(sem.value(*o, id.pair, p01)).margin(1e-6));
  CHECK(q["Tall"]["i2"].get<double>() + q["Short"]["i2"].get<double>() == Approx(1.0).margin(2e-6));
  CHECK(q.dump() == sem.queries_json(*o, kNames3).dump());  // deterministic

  const std::string db = sem.evidence_db(*o, kNames3);
  CHECK(db.find("near(i0,i1)\n") != std::string::npos);
  CHECK(db.find("!near(i0,i0)\n") != std::string::npos);
  CHECK(db.find("big(i2)\n") != std::string::npos);
  CHECK(db.find("Pair") == std::string::npos);  // evidence atoms only
  // ksmc infer reads it: constants from the .db, every evidence atom as extracted.
  const auto& p = ksmc::tests::domain::toy_program();
  mln::Domain d = ksmc::tests::domain::toy_make_domain();
  mln::collect_db_constants(db, "evidence.db", p, d);
  REQUIRE(d.size(id.item) == 3);
  mln::Evidence ev(p, d);
  mln::parse_db(db, "evidence.db", p, d, ev);
  for (const std::int32_t pred : {id.near, id.big}) {
    for (std::int64_t k = 0; k < ev.num_atoms(pred); ++k)
      CHECK(ev.get_flat(pred, k) == static_cast<std::int8_t>(o->values[static_cast<std::size_t>(pred)][static_cast<std::size_t>(k)]));
  }
  CHECK_THROWS_AS(sem.evidence_db(*o, {"i0"}), std::invalid_argument);
}

TEST_CASE("semantics: a binding the program does not fit is a ConfigError", "[domain][semantics]") {
  const auto& id = toy_ids();
  auto b = toy_binding();
  b.extractors.push_back({id.pair, &ksmc::tests::domain::extract_near, "extract Pair"});
  CHECK_THROWS_AS(dom::Semantics<ToyScene>(b), dom::ConfigError);
  b = toy_binding();
  b.extractors.push_back({id.near, &ksmc::tests::domain::extract_near, "again"});
  CHECK_THROWS_AS(dom::Semantics<ToyScene>(b), dom::ConfigError);
  b = toy_binding();
  b.constant_type = 7;
  CHECK_THROWS_AS(dom::Semantics<ToyScene>(b), dom::ConfigError);
  b = toy_binding();
  b.mln.ground = nullptr;
  CHECK_THROWS_AS(dom::Semantics<ToyScene>(b), dom::ConfigError);
}

TEST_CASE("labels: exactly-one-of groups of unary query predicates over the constant type", "[domain][labels]") {
  const auto& p = ksmc::tests::domain::toy_program();
  const auto& id = toy_ids();
  const auto groups = dom::label_groups(p, id.item);
  REQUIRE(groups.size() == 1);
  CHECK(groups[0].predicates == std::vector<std::int32_t>{id.tall, id.shorty});
  CHECK(dom::label_groups(p, id.color).empty());
  CHECK(dom::most_probable({0.2, 0.5, 0.5}) == 1);
}
