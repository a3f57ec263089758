// The table-top knowledge base of domains/tabletop.ksm built as a runtime Program by hand:
// the seed's Table 4.3 (DESIGN.md section 3, r1..r16) plus the domain file's additions
// r17..r26 and r28..r32 (docs/tabletop_kit.md, "Knowledge base"). 31 rules; r10's conjunctive
// consequent becomes two clauses (r10a, r10b).
// Soft weights are log-odds: prob p -> log(p / (1 - p)).
#pragma once

#include <cmath>
#include <initializer_list>
#include <string>

#include "runtime/mln/program.h"

namespace ksmc::tests::mln {

struct TabletopKb {
  runtime::mln::Program program;
  std::int32_t object = 0;
  std::int32_t stable = 0, table = 0, hover = 0, contact = 0, intersect = 0, higher = 0;
  std::int32_t supported = 0, supportive = 0, hidden = 0, false_est = 0;
  std::int32_t overlap = 0, flatter = 0, overhang = 0, leaning = 0, snugger = 0, blocks = 0, hides = 0, tilted = 0,
               sunk = 0;

  TabletopKb() {
    using namespace runtime::mln;
    object = program.add_type("object");
    auto pred = [&](const char* name, int arity, bool query) {
      Predicate p;
      p.name = name;
      p.arg_types.assign(static_cast<std::size_t>(arity), object);
      p.query = query;
      return program.add_predicate(p);
    };
    stable = pred("stable", 1, false);
    table = pred("table", 1, false);
    hover = pred("hover", 1, false);
    contact = pred("contact", 2, false);
    intersect = pred("intersect", 2, false);
    higher = pred("higher", 2, false);
    supported = pred("supported", 1, true);
    supportive = pred("supportive", 1, true);
    hidden = pred("hidden", 1, true);
    false_est = pred("falseEst", 1, true);
    overlap = pred("overlap", 2, false);
    flatter = pred("flatter", 2, false);
    overhang = pred("overhang", 1, false);
    leaning = pred("leaning", 1, false);
    snugger = pred("snugger", 2, false);
    blocks = pred("blocks", 2, false);
    hides = pred("hides", 2, false);
    tilted = pred("tilted", 1, false);
    sunk = pred("sunk", 1, false);

    // Literal shorthand: P(o) / !P(o) over variables 0 (o1) and 1 (o2).
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
      c.loc = {"tabletop.ksm", line};
      c.hard = prob >= 1.0;
      c.weight = c.hard ? 0.0 : std::log(prob / (1.0 - prob));
      for (int v = 0; v < nvars; ++v) c.variables.push_back({v == 0 ? "o1" : "o2", object, false});
      for (const auto& l : lits) {
        Literal lit;
        lit.predicate = l.p;
        lit.negated = l.neg;
        for (auto v : l.vars) lit.args.push_back(Term::var(v));
        c.literals.push_back(lit);
      }
      program.add_clause(c);
    };
    rule("r1", 10, 1.0, "!higher(o1, o1)", 1, {{higher, true, {0, 0}}});
    rule("r2", 11, 1.0, "!intersect(o1, o1)", 1, {{intersect, true, {0, 0}}});
    rule("r3", 12, 1.0, "!contact(o1, o1)", 1, {{contact, true, {0, 0}}});
    rule("r4", 13, 1.0, "contact(o1, o2) => contact(o2, o1)", 2,
         {{contact, true, {0, 1}}, {contact, false, {1, 0}}});
    rule("r5", 14, 1.0, "intersect(o1, o2) => intersect(o2, o1)", 2,
         {{intersect, true, {0, 1}}, {intersect, false, {1, 0}}});
    rule("r6", 15, 1.0, "higher(o1, o2) => !higher(o2, o1)", 2, {{higher, true, {0, 1}}, {higher, true, {1, 0}}});
    rule("r7", 16, 1.0, "table(o1) => !falseEst(o1)", 1, {{table, true, {0}}, {false_est, true, {0}}});
    rule("r8", 17, 1.0, "table(o1) => !hidden(o1)", 1, {{table, true, {0}}, {hidden, true, {0}}});
    rule("r9", 18, 1.0, "table(o1) => stable(o1)", 1, {{table, true, {0}}, {stable, false, {0}}});
    const char* r10 = "stable(o1) ^ stable(o2) ^ contact(o1, o2) ^ higher(o1, o2) => supportive(o2) ^ supported(o1)";
    rule("r10", 19, 1.0, r10, 2,
         {{stable, true, {0}}, {stable, true, {1}}, {contact, true, {0, 1}}, {higher, true, {0, 1}},
          {supportive, false, {1}}});
    rule("r10", 19, 1.0, r10, 2,
         {{stable, true, {0}}, {stable, true, {1}}, {contact, true, {0, 1}}, {higher, true, {0, 1}},
          {supported, false, {0}}});
    rule("r11", 20, 0.7, "supported(o1) => !hidden(o1)", 1, {{supported, true, {0}}, {hidden, true, {0}}});
    rule("r12", 21, 0.9, "!stable(o1) => !supportive(o1)", 1, {{stable, false, {0}}, {supportive, true, {0}}});
    rule("r13", 22, 0.9, "hover(o1) => falseEst(o1) v hidden(o1)", 1,
         {{hover, true, {0}}, {false_est, false, {0}}, {hidden, false, {0}}});
    rule("r14", 23, 0.9, "intersect(o1, o2) => falseEst(o1) v falseEst(o2)", 2,
         {{intersect, true, {0, 1}}, {false_est, false, {0}}, {false_est, false, {1}}});
    rule("r15", 24, 0.7, "supportive(o1) => !falseEst(o1)", 1, {{supportive, true, {0}}, {false_est, true, {0}}});
    rule("r16", 25, 0.9, "stable(o1) => !falseEst(o1)", 1, {{stable, true, {0}}, {false_est, true, {0}}});
    // Additions of domains/tabletop.ksm (its lines 41-135).
    rule("r17", 41, 0.9, "!supported(o1)", 1, {{supported, true, {0}}});
    rule("r18", 46, 0.9, "stable(o1) ^ !table(o1) => supported(o1) v hidden(o1) v falseEst(o1)", 1,
         {{stable, true, {0}}, {table, false, {0}}, {supported, false, {0}}, {hidden, false, {0}},
          {false_est, false, {0}}});
    rule("r19", 49, 0.9, "intersect(o1, o2) ^ supported(o2) ^ !supported(o1) ^ !leaning(o1) => falseEst(o1)", 2,
         {{intersect, true, {0, 1}}, {supported, true, {1}}, {supported, false, {0}}, {leaning, false, {0}},
          {false_est, false, {0}}});
    rule("r20", 53, 0.9, "!stable(o1) => !hidden(o1)", 1, {{stable, false, {0}}, {hidden, true, {0}}});
    rule("r21", 57, 0.7, "!falseEst(o1)", 1, {{false_est, true, {0}}});
    rule("r22", 58, 0.65, "!hidden(o1)", 1, {{hidden, true, {0}}});
    rule("r23", 66, 0.9, "overlap(o1, o2) ^ stable(o1) ^ stable(o2) ^ flatter(o1, o2) => falseEst(o2)", 2,
         {{overlap, true, {0, 1}}, {stable, true, {0}}, {stable, true, {1}}, {flatter, true, {0, 1}},
          {false_est, false, {1}}});
    rule("r24", 74, 0.9, "stable(o1) ^ overhang(o1) => falseEst(o1) v hidden(o1)", 1,
         {{stable, true, {0}}, {overhang, true, {0}}, {false_est, false, {0}}, {hidden, false, {0}}});
    rule("r25", 81, 0.95, "leaning(o1) => !falseEst(o1)", 1, {{leaning, true, {0}}, {false_est, true, {0}}});
    rule("r26", 88, 0.75, "intersect(o1, o2) ^ stable(o1) ^ stable(o2) ^ snugger(o1, o2) => falseEst(o2)", 2,
         {{intersect, true, {0, 1}}, {stable, true, {0}}, {stable, true, {1}}, {snugger, true, {0, 1}},
          {false_est, false, {1}}});
    rule("r28", 95, 0.9, "blocks(o1, o2) => falseEst(o1) v falseEst(o2)", 2,
         {{blocks, true, {0, 1}}, {false_est, false, {0}}, {false_est, false, {1}}});
    rule("r29", 102, 0.75, "blocks(o1, o2) ^ !blocks(o2, o1) => falseEst(o1)", 2,
         {{blocks, true, {0, 1}}, {blocks, false, {1, 0}}, {false_est, false, {0}}});
    rule("r30", 109, 0.75, "intersect(o1, o2) ^ hides(o1, o2) ^ !blocks(o1, o2) => falseEst(o2)", 2,
         {{intersect, true, {0, 1}}, {hides, true, {0, 1}}, {blocks, false, {0, 1}}, {false_est, false, {1}}});
    rule("r31", 118, 0.99, "hover(o1) ^ tilted(o1) => falseEst(o1)", 1,
         {{hover, true, {0}}, {tilted, true, {0}}, {false_est, false, {0}}});
    rule("r32", 125, 0.9, "!hover(o1)", 1, {{hover, true, {0}}});
    rule("r33", 135, 0.9, "tilted(o1) ^ sunk(o1) => falseEst(o1)", 1,
         {{tilted, true, {0}}, {sunk, true, {0}}, {false_est, false, {0}}});
  }
};

}  // namespace ksmc::tests::mln
