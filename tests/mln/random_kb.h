// Random small knowledge bases for property tests: 2-3 predicates over one type with
// 2-4 constants, random soft/hard clauses (some with existential variables), random
// evidence and sometimes exactly-one constraints. At most `max_free` query atoms.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <string>

#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace ksmc::tests::mln {

struct RandomKb {
  runtime::mln::Program program;
  runtime::mln::Domain domain;
  std::unique_ptr<runtime::mln::Evidence> evidence;
};

inline RandomKb make_random_kb(std::mt19937_64& rng, int max_free = 12) {
  using namespace runtime::mln;
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  while (true) {
    RandomKb kb;
    const auto t = kb.program.add_type("t");
    const int nc = uni(2, 4);
    kb.domain.resize(1);
    for (int i = 0; i < nc; ++i) kb.domain.add(t, "C" + std::to_string(i));
    const int np = uni(2, 3);
    int free = 0;
    for (int p = 0; p < np; ++p) {
      Predicate pr;
      pr.name = "P" + std::to_string(p);
      const int arity = (nc <= 3 && uni(0, 2) == 0) ? 2 : 1;
      pr.arg_types.assign(static_cast<std::size_t>(arity), t);
      pr.query = p == 0 || uni(0, 1) == 0;
      if (pr.query && arity == 2 && uni(0, 4) == 0) pr.exclusive_arg = 1;
      if (pr.query) free += arity == 2 ? nc * nc : nc;
      kb.program.add_predicate(pr);
    }
    if (free > max_free) continue;
    // exactly-one group of unary query predicates, sometimes
    std::vector<std::int32_t> unary_q;
    for (int p = 0; p < np; ++p)
      if (kb.program.predicates[p].query && kb.program.predicates[p].arg_types.size() == 1) unary_q.push_back(p);
    if (unary_q.size() >= 2 && uni(0, 3) == 0) kb.program.add_group({unary_q, "exactly one", {"random.ksm", 1}});
    const int ncl = uni(2, 5);
    for (int k = 0; k < ncl; ++k) {
      Clause c;
      c.name = "c" + std::to_string(k);
      c.text = "random clause " + std::to_string(k);
      c.loc = {"random.ksm", k + 2};
      const int nvars = uni(1, 2);
      for (int v = 0; v < nvars; ++v) c.variables.push_back({"x" + std::to_string(v), t, false});
      if (uni(0, 9) == 0) c.variables.push_back({"e", t, true});
      const int nl = uni(1, 3);
      for (int l = 0; l < nl; ++l) {
        Literal lit;
        lit.predicate = uni(0, np - 1);
        lit.negated = uni(0, 1) == 1;
        for (std::size_t a = 0; a < kb.program.predicates[lit.predicate].arg_types.size(); ++a) {
          if (uni(0, 9) == 0) lit.args.push_back(Term::cst("C0"));
          else lit.args.push_back(Term::var(uni(0, static_cast<int>(c.variables.size()) - 1)));
        }
        c.literals.push_back(lit);
      }
      c.hard = uni(0, 4) == 0;
      c.weight = c.hard ? 0.0 : real(-2.0, 2.5);
      kb.program.add_clause(c);
    }
    kb.evidence = std::make_unique<Evidence>(kb.program, kb.domain);
    for (int p = 0; p < np; ++p) {
      if (kb.program.predicates[p].query) {
        // Sometimes fix a few query atoms too (exercises folding of fixed query atoms
        // and of exactly-one blocks).
        if (uni(0, 3) != 0) continue;
        kb.program.predicates[p].query_evidence_allowed = true;
        for (std::int64_t f = 0; f < kb.evidence->num_atoms(p); ++f) {
          const int r = uni(0, 9);
          if (r < 2) kb.evidence->set_flat(p, f, 1);
          else if (r < 4) kb.evidence->set_flat(p, f, 0);
        }
        continue;
      }
      for (std::int64_t f = 0; f < kb.evidence->num_atoms(p); ++f) {
        const int r = uni(0, 9);
        if (r < 4) kb.evidence->set_flat(p, f, 1);
        else if (r < 6) kb.evidence->set_flat(p, f, 0);
      }
    }
    return kb;
  }
}

}  // namespace ksmc::tests::mln
