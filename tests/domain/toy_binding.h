// A small hand-written domain for the shared kit layer's tests: what generated
// `<domain>_factors.h` / `<domain>_model.cpp` would give for
//
//   type item;  type color = {red, green};
//   evidence near(item, item), big(item);
//   query Pair(item, item), Tall(item), Short(item), Paint(item, color);
//   hard exactly one of Tall(i), Short(i).
//   hard !Pair(a, a).
//   prob 0.8: near(a, b) => Pair(a, b).
//   prob 0.9: big(a) => Tall(a).
//   prob 0.6: Paint(a, red).
//   hard big(a) ^ big(b) ^ a != b => !near(a, b).   (as: !big(a) v !big(b) v !near(a, b))
//   extract near(a, b) = |x[a] - x[b]| < 1;  extract big(a) = x[a] > 5;
//   prior for a, b where P(Pair(a, b)) > 0.5: -(x[a] - x[b])^2;
//   prior for a where !big(a): -1;
//
// The scene is a list of positions on a line.
#pragma once

#include <cmath>
#include <initializer_list>
#include <vector>

#include "runtime/domain/binding.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/program.h"

namespace ksmc::tests::domain {

struct ToyScene {
  std::vector<double> x;
  double at(std::int32_t c) const { return x[static_cast<std::size_t>(c)]; }
};

struct ToyIds {
  std::int32_t item = 0, color = 0;
  std::int32_t near = 0, big = 0, pair = 0, tall = 0, shorty = 0, paint = 0;
};

inline ToyIds& toy_ids() {
  static ToyIds ids;
  return ids;
}

inline const runtime::mln::Program& toy_program() {
  static const runtime::mln::Program program = [] {
    using namespace runtime::mln;
    ToyIds& id = toy_ids();
    Program p;
    id.item = p.add_type("item");
    id.color = p.add_type("color");
    auto pred = [&](const char* name, std::vector<std::int32_t> types, bool query) {
      Predicate x;
      x.name = name;
      x.arg_types = std::move(types);
      x.query = query;
      return p.add_predicate(x);
    };
    id.near = pred("near", {id.item, id.item}, false);
    id.big = pred("big", {id.item}, false);
    id.pair = pred("Pair", {id.item, id.item}, true);
    id.tall = pred("Tall", {id.item}, true);
    id.shorty = pred("Short", {id.item}, true);
    id.paint = pred("Paint", {id.item, id.color}, true);
    p.add_group({{id.tall, id.shorty}, "exactly one of Tall(i), Short(i)", {"toy.ksm", 4}});
    struct L {
      std::int32_t p;
      bool neg;
      std::vector<Term> args;
    };
    auto rule = [&](const char* name, double prob, std::vector<Variable> vars, std::initializer_list<L> lits) {
      Clause c;
      c.name = name;
      c.text = name;
      c.hard = prob >= 1.0;
      c.weight = c.hard ? 0.0 : std::log(prob / (1.0 - prob));
      c.variables = std::move(vars);
      for (const auto& l : lits) c.literals.push_back({l.p, l.neg, l.args});
      p.add_clause(c);
    };
    const Variable a{"a", id.item, false}, b{"b", id.item, false};
    rule("irreflexive", 1.0, {a}, {{id.pair, true, {Term::var(0), Term::var(0)}}});
    rule("near_pair", 0.8, {a, b}, {{id.near, true, {Term::var(0), Term::var(1)}}, {id.pair, false, {Term::var(0), Term::var(1)}}});
    rule("big_tall", 0.9, {a}, {{id.big, true, {Term::var(0)}}, {id.tall, false, {Term::var(0)}}});
    rule("red", 0.6, {a}, {{id.paint, false, {Term::var(0), Term::cst("red")}}});
    rule("bigs_apart", 1.0, {a, b},
         {{id.big, true, {Term::var(0)}}, {id.big, true, {Term::var(1)}}, {id.near, true, {Term::var(0), Term::var(1)}}});
    p.validate();
    return p;
  }();
  return program;
}

inline runtime::mln::Domain toy_make_domain() {
  const auto& p = toy_program();
  runtime::mln::Domain d(p.types.size());
  d.add(toy_ids().color, "red");
  d.add(toy_ids().color, "green");
  return d;
}

inline runtime::mln::Grounding toy_ground(const runtime::mln::Domain& d, const runtime::mln::Evidence& e) {
  return runtime::mln::ground(toy_program(), d, e);
}

inline bool extract_near(const ToyScene& s, const std::int32_t* c) { return std::abs(s.at(c[0]) - s.at(c[1])) < 1.0; }
inline bool extract_big(const ToyScene& s, const std::int32_t* c) { return s.at(c[0]) > 5.0; }
inline double term_pair(const ToyScene& s, const std::int32_t* c) {
  const double d = s.at(c[0]) - s.at(c[1]);
  return -d * d;
}
inline double term_small(const ToyScene&, const std::int32_t*) { return -1.0; }

inline runtime::domain::SemanticBinding<ToyScene> toy_binding() {
  namespace dom = runtime::domain;
  (void)toy_program();
  const ToyIds& id = toy_ids();
  dom::SemanticBinding<ToyScene> b;
  b.mln = {&toy_program, &toy_make_domain, &toy_ground};
  b.constant_type = id.item;
  b.extractors.push_back({id.near, &extract_near, "extract near(a, b)"});
  b.extractors.push_back({id.big, &extract_big, "extract big(a)"});
  b.conditional_priors.push_back(
      {{id.item, id.item}, {{true, id.pair, {0, 1}, dom::Cmp::gt, 0.5, false}}, &term_pair, "prior for a, b where P(Pair(a, b)) > 0.5"});
  b.conditional_priors.push_back({{id.item}, {{false, id.big, {0}, dom::Cmp::gt, 0.0, true}}, &term_small, "prior for a where !big(a)"});
  return b;
}

}  // namespace ksmc::tests::domain
