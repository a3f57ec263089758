// The indoor knowledge base of DESIGN.md section 6 built as a runtime Program (a
// stand-in until the compiler lowers domains/indoor.ksm): an exactly-one group over
// the unit types and the symmetric, adjacency-gated SaLe relation.
#pragma once

#include <cmath>
#include <initializer_list>

#include "runtime/mln/program.h"

namespace ksmc::tests::mln {

struct IndoorKb {
  runtime::mln::Program program;
  std::int32_t unit = 0;
  std::int32_t roli = 0, coli = 0, hali = 0, muldoor = 0, adj = 0, thin = 0, blocked = 0, hollow = 0, open_join = 0;
  std::int32_t narrow = 0, end_join = 0;
  std::int32_t room = 0, corr = 0, hall = 0, other = 0, sale = 0;

  // only_seed_rules: the rules of DESIGN.md section 6 and the defect rules, without the two
  // that keep SaLe off for pairs that are not two rooms (test_indoor's MC-SAT check).
  explicit IndoorKb(bool only_seed_rules = false) {
    using namespace runtime::mln;
    unit = program.add_type("unit");
    auto pred = [&](const char* name, int arity, bool query) {
      Predicate p;
      p.name = name;
      p.arg_types.assign(static_cast<std::size_t>(arity), unit);
      p.query = query;
      return program.add_predicate(p);
    };
    roli = pred("RoLi", 1, false);
    coli = pred("CoLi", 1, false);
    hali = pred("HaLi", 1, false);
    muldoor = pred("MulDoor", 1, false);
    adj = pred("Adj", 2, false);
    thin = pred("Thin", 1, false);
    blocked = pred("Blocked", 1, false);
    hollow = pred("Hollow", 1, false);
    open_join = pred("OpenJoin", 2, false);
    narrow = pred("Narrow", 1, false);
    end_join = pred("EndJoin", 2, false);
    room = pred("Room", 1, true);
    corr = pred("Corr", 1, true);
    hall = pred("Hall", 1, true);
    other = pred("Other", 1, true);
    sale = pred("SaLe", 2, true);
    program.add_group({{room, corr, hall, other}, "exactly one of Room(u), Corr(u), Hall(u), Other(u)",
                       {"indoor.ksm", 10}});
    struct L {
      std::int32_t p;
      bool neg;
      std::initializer_list<std::int32_t> vars;
    };
    auto rule = [&](const char* name, int line, double prob, const char* text, int nvars,
                    std::initializer_list<L> lits) {
      Clause c;
      c.name = name;
      c.text = text;
      c.loc = {"indoor.ksm", line};
      c.hard = prob >= 1.0;
      c.weight = c.hard ? 0.0 : std::log(prob / (1.0 - prob));
      for (int v = 0; v < nvars; ++v) c.variables.push_back({v == 0 ? "a" : "b", unit, false});
      for (const auto& l : lits) {
        Literal lit{l.p, l.neg, {}};
        for (auto v : l.vars) lit.args.push_back(Term::var(v));
        c.literals.push_back(lit);
      }
      program.add_clause(c);
    };
    rule("i2", 11, 1.0, "!SaLe(u, u)", 1, {{sale, true, {0, 0}}});
    rule("i3", 12, 1.0, "SaLe(a, b) => SaLe(b, a)", 2, {{sale, true, {0, 1}}, {sale, false, {1, 0}}});
    rule("i4", 13, 1.0, "!Adj(a, b) => !SaLe(a, b)", 2, {{adj, false, {0, 1}}, {sale, true, {0, 1}}});
    rule("i5", 14, 0.9, "RoLi(u) => Room(u)", 1, {{roli, true, {0}}, {room, false, {0}}});
    rule("i6", 15, 0.9, "CoLi(u) => Corr(u)", 1, {{coli, true, {0}}, {corr, false, {0}}});
    rule("i7", 16, 0.9, "HaLi(u) => Hall(u)", 1, {{hali, true, {0}}, {hall, false, {0}}});
    rule("i8", 17, 0.8, "MulDoor(u) ^ CoLi(u) => Corr(u)", 1,
         {{muldoor, true, {0}}, {coli, true, {0}}, {corr, false, {0}}});
    rule("i9", 18, 0.7, "MulDoor(u) => !Room(u)", 1, {{muldoor, true, {0}}, {room, true, {0}}});
    rule("i10", 19, 0.9, "Room(a) ^ Room(b) ^ Adj(a, b) => SaLe(a, b)", 2,
         {{room, true, {0}}, {room, true, {1}}, {adj, true, {0, 1}}, {sale, false, {0, 1}}});
    // Only two rooms share a wall length (issue 11): SaLe off for every other adjacent pair.
    if (!only_seed_rules) rule("sale_none", 29, 0.9, "Adj(a, b) ^ !Room(a) ^ !Room(b) => !SaLe(a, b)", 2,
         {{adj, true, {0, 1}}, {room, false, {0}}, {room, false, {1}}, {sale, true, {0, 1}}});
    if (!only_seed_rules) rule("sale_one", 30, std::exp(4.394449) / (1.0 + std::exp(4.394449)), "Adj(a, b) ^ Room(a) ^ !Room(b) => !SaLe(a, b)", 2,
         {{adj, true, {0, 1}}, {room, true, {0}}, {room, false, {1}}, {sale, true, {0, 1}}});
    // The knowledge against topological defects (issue 11): evidence only.
    rule("no_sliver", 31, 1.0, "!Thin(u)", 1, {{thin, true, {0}}});
    rule("not_wall", 33, 1.0, "!Blocked(u)", 1, {{blocked, true, {0}}});
    rule("no_hollow", 37, 1.0, "!Hollow(u)", 1, {{hollow, true, {0}}});
    rule("one_space", 48, std::exp(10.0) / (1.0 + std::exp(10.0)), "!OpenJoin(a, b)", 2, {{open_join, true, {0, 1}}});
    rule("corr_continues", 52, std::exp(4.0) / (1.0 + std::exp(4.0)), "Narrow(a) ^ OpenJoin(a, b) ^ EndJoin(a, b) ^ Corr(b) => Corr(a)", 2,
         {{narrow, true, {0}}, {open_join, true, {0, 1}}, {end_join, true, {0, 1}}, {corr, true, {1}}, {corr, false, {0}}});
  }
};

}  // namespace ksmc::tests::mln
