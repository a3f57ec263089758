// Independent reference for the tests: enumerates every world of the FULL ground MLN
// (all groundings of every clause, evidence atoms fixed by closed world, no folding,
// no components) and returns marginals per query atom and log Z. Written without the
// runtime's grounder, network or engines; only the Program/Domain data types are read.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "runtime/mln/evidence.h"
#include "runtime/mln/program.h"

namespace ksmc::tests::mln {

struct BruteResult {
  bool feasible = false;
  std::vector<double> marginal;  // indexed [predicate][flat] flattened as below
  std::vector<std::int64_t> base; // per predicate, start in `marginal` (all predicates)
  double log_z = 0.0;
  double at(std::int32_t p, std::int64_t flat) const { return marginal[base[p] + flat]; }
};

inline BruteResult brute_force(const runtime::mln::Program& prog, const runtime::mln::Domain& dom,
                               const runtime::mln::Evidence& ev) {
  using runtime::mln::Evidence;
  const auto np = prog.predicates.size();
  BruteResult r;
  std::vector<std::vector<std::int64_t>> radix(np);
  std::int64_t total = 0;
  for (std::size_t p = 0; p < np; ++p) {
    r.base.push_back(total);
    std::int64_t n = 1;
    for (auto t : prog.predicates[p].arg_types) {
      radix[p].push_back(dom.size(t));
      n *= dom.size(t);
    }
    total += n;
  }
  // World: value per atom; free = query atoms without evidence.
  std::vector<std::uint8_t> world(static_cast<std::size_t>(total), 0);
  std::vector<std::int64_t> free_atoms;
  for (std::size_t p = 0; p < np; ++p) {
    const auto n = ev.num_atoms(static_cast<std::int32_t>(p));
    for (std::int64_t f = 0; f < n; ++f) {
      const auto v = ev.get_flat(static_cast<std::int32_t>(p), f);
      if (prog.predicates[p].query && v == Evidence::kUnknown) free_atoms.push_back(r.base[p] + f);
      else world[r.base[p] + f] = v == 1 ? 1 : 0;
    }
  }
  auto atom_of = [&](std::int32_t p, const std::vector<std::int64_t>& args) {
    std::int64_t flat = 0;
    for (std::size_t i = 0; i < args.size(); ++i) flat = flat * radix[p][i] + args[i];
    return r.base[p] + flat;
  };
  // Returns log-weight of the world or nullopt if it violates a hard clause / block.
  auto evaluate = [&]() -> std::optional<double> {
    for (const auto& g : prog.groups) {
      const auto n = ev.num_atoms(g.predicates[0]);
      for (std::int64_t f = 0; f < n; ++f) {
        int on = 0;
        for (auto p : g.predicates) on += world[r.base[p] + f];
        if (on != 1) return std::nullopt;
      }
    }
    for (std::size_t p = 0; p < np; ++p) {
      const auto e = prog.predicates[p].exclusive_arg;
      if (e < 0) continue;
      const auto n = ev.num_atoms(static_cast<std::int32_t>(p));
      std::int64_t inner = 1;
      for (std::size_t i = static_cast<std::size_t>(e) + 1; i < radix[p].size(); ++i) inner *= radix[p][i];
      for (std::int64_t f = 0; f < n; ++f) {
        if ((f / inner) % radix[p][e] != 0) continue;
        int on = 0;
        for (std::int64_t k = 0; k < radix[p][e]; ++k) on += world[r.base[p] + f + k * inner];
        if (on != 1) return std::nullopt;
      }
    }
    double s = 0.0;
    for (const auto& c : prog.clauses) {
      const auto nv = c.variables.size();
      std::vector<std::int64_t> val(nv, 0);
      std::vector<std::int32_t> uni, exi;
      for (std::size_t v = 0; v < nv; ++v) (c.variables[v].existential ? exi : uni).push_back(static_cast<std::int32_t>(v));
      bool any_empty = false;
      for (auto v : uni) any_empty = any_empty || dom.size(c.variables[v].type) == 0;
      if (any_empty) continue;
      while (true) {
        // satisfied if some literal is true for some assignment of existential vars
        bool sat = false;
        std::vector<std::int64_t> ev_val(nv, 0);
        bool exi_empty = false;
        for (auto v : exi) exi_empty = exi_empty || dom.size(c.variables[v].type) == 0;
        while (!exi_empty && !sat) {
          for (const auto& l : c.literals) {
            std::vector<std::int64_t> args;
            for (std::size_t i = 0; i < l.args.size(); ++i) {
              const auto& t = l.args[i];
              if (!t.is_variable) args.push_back(*dom.find(prog.predicates[l.predicate].arg_types[i], t.constant));
              else args.push_back(c.variables[t.variable].existential ? ev_val[t.variable] : val[t.variable]);
            }
            if ((world[atom_of(l.predicate, args)] == 1) != l.negated) { sat = true; break; }
          }
          std::size_t j = 0;
          for (; j < exi.size(); ++j) {
            if (++ev_val[exi[j]] < dom.size(c.variables[exi[j]].type)) break;
            ev_val[exi[j]] = 0;
          }
          if (j == exi.size()) break;
        }
        if (c.hard && !sat) return std::nullopt;
        if (!c.hard && sat) s += c.weight;
        std::size_t j = 0;
        for (; j < uni.size(); ++j) {
          if (++val[uni[j]] < dom.size(c.variables[uni[j]].type)) break;
          val[uni[j]] = 0;
        }
        if (j == uni.size()) break;
      }
    }
    return s;
  };
  const auto nf = free_atoms.size();
  std::vector<double> logw;
  std::vector<std::uint64_t> masks;
  for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << nf); ++mask) {
    for (std::size_t i = 0; i < nf; ++i) world[free_atoms[i]] = (mask >> i) & 1;
    if (auto s = evaluate()) {
      logw.push_back(*s);
      masks.push_back(mask);
    }
  }
  r.marginal.assign(static_cast<std::size_t>(total), 0.0);
  if (logw.empty()) return r;
  r.feasible = true;
  double mx = -std::numeric_limits<double>::infinity();
  for (double s : logw) mx = std::max(mx, s);
  double z = 0.0;
  std::vector<double> acc(nf, 0.0);
  for (std::size_t k = 0; k < logw.size(); ++k) {
    const double w = std::exp(logw[k] - mx);
    z += w;
    for (std::size_t i = 0; i < nf; ++i)
      if ((masks[k] >> i) & 1) acc[i] += w;
  }
  r.log_z = mx + std::log(z);
  for (std::size_t p = 0; p < np; ++p) {  // fixed atoms: their value
    const auto n = ev.num_atoms(static_cast<std::int32_t>(p));
    for (std::int64_t f = 0; f < n; ++f) r.marginal[r.base[p] + f] = world[r.base[p] + f];
  }
  for (std::size_t i = 0; i < nf; ++i) r.marginal[free_atoms[i]] = acc[i] / z;
  return r;
}

}  // namespace ksmc::tests::mln
