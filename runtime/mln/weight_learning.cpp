#include "runtime/mln/weight_learning.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>

#include "runtime/mln/error.h"
#include "runtime/mln/components.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/mcsat.h"

namespace ksmc::runtime::mln {
namespace {

using Features = std::vector<std::pair<std::int32_t, double>>;  // (param, count), sparse

// A clause's share: its parameter and scale, or -1 and its fixed weight.
struct Share {
  std::int32_t param = -1;
  double scale = 0.0;  // param >= 0
  double fixed = 0.0;  // param < 0
};

Share share_of(const GroundNetwork& net, std::int32_t c, const WeightTying& tying) {
  Share s;
  const std::int32_t origin = net.origin(c);
  if (!net.is_hard(c) && origin >= 0 && static_cast<std::size_t>(origin) < tying.param_of_clause.size() &&
      tying.param_of_clause[origin] >= 0) {
    s.param = tying.param_of_clause[origin];
    s.scale = tying.scale_of_clause[origin];
  } else if (!net.is_hard(c)) {
    s.fixed = net.weight(c);
  }
  return s;
}

bool satisfied(const GroundNetwork& net, std::int32_t c, std::span<const std::uint8_t> x) {
  for (Lit l : net.clause(c))
    if (lit_true(l, x[lit_atom(l)])) return true;
  return false;
}

void add_feature(Features& f, std::int32_t param, double v) {
  for (auto& [p, x] : f)
    if (p == param) { x += v; return; }
  f.push_back({param, v});
}

// The conditional of one variable given the rest of one world (repeated `count` times).
struct Conditional {
  double count = 1.0;
  std::int32_t observed = 0;
  std::vector<std::uint8_t> allowed;
  std::vector<double> fixed;
  std::vector<Features> feats;
};

std::string world_error(std::size_t set, std::size_t world, const std::string& what) {
  return "training set " + std::to_string(set + 1) + ", world " + std::to_string(world + 1) + ": " + what;
}

// Identical worlds of a set merged, with their counts.
std::vector<std::pair<std::vector<std::uint8_t>, double>> merge_worlds(const TrainingSet& ts, std::size_t set) {
  std::map<std::vector<std::uint8_t>, double> counts;
  for (std::size_t w = 0; w < ts.worlds.size(); ++w) {
    const auto& x = ts.worlds[w];
    if (x.size() != static_cast<std::size_t>(ts.network.num_atoms()))
      throw MlnError(world_error(set, w, "has " + std::to_string(x.size()) + " values for " +
                                           std::to_string(ts.network.num_atoms()) + " free atoms"));
    if (!ts.network.feasible(x)) {
      std::string rules;
      for (std::int32_t c = 0; c < ts.network.num_clauses(); ++c)
        if (ts.network.is_hard(c) && !satisfied(ts.network, c, x)) { rules = ts.network.origin_name(c); break; }
      throw MlnError(world_error(set, w, rules.empty() ? "breaks an exactly-one block" : "breaks hard rule " + rules));
    }
    counts[x] += 1.0;
  }
  return {counts.begin(), counts.end()};
}

std::vector<Conditional> tabulate_pll(std::span<const TrainingSet> data, const WeightTying& tying, double& worlds) {
  std::vector<Conditional> out;
  worlds = 0.0;
  for (std::size_t si = 0; si < data.size(); ++si) {
    const GroundNetwork& net = data[si].network;
    const Occurrences occ = build_occurrences(net);
    // variables: plain atoms, then blocks
    std::vector<std::vector<AtomId>> vars;
    for (AtomId a = 0; a < net.num_atoms(); ++a)
      if (net.block_of(a) < 0) vars.push_back({a});
    for (std::int32_t b = 0; b < net.num_blocks(); ++b) {
      const auto atoms = net.block(b);
      vars.emplace_back(atoms.begin(), atoms.end());
    }
    std::vector<Share> shares;
    for (std::int32_t c = 0; c < net.num_clauses(); ++c) shares.push_back(share_of(net, c, tying));
    std::vector<std::int32_t> touched;
    for (auto& [world, count] : merge_worlds(data[si], si)) {
      worlds += count;
      std::vector<std::uint8_t> x = world;
      for (const auto& atoms : vars) {
        touched.clear();
        for (AtomId a : atoms)
          for (std::int32_t c : occ.clauses_of(a)) touched.push_back(c);
        std::sort(touched.begin(), touched.end());
        touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
        Conditional cond;
        cond.count = count;
        const bool block = atoms.size() > 1 || net.block_of(atoms[0]) >= 0;
        const std::size_t nv = block ? atoms.size() : 2;
        for (std::size_t u = 0; u < nv; ++u) {
          if (block) {
            for (std::size_t k = 0; k < atoms.size(); ++k) x[atoms[k]] = k == u ? 1 : 0;
            if (world[atoms[u]]) cond.observed = static_cast<std::int32_t>(u);
          } else {
            x[atoms[0]] = static_cast<std::uint8_t>(u);
          }
          bool ok = true;
          double fixed = 0.0;
          Features f;
          for (std::int32_t c : touched) {
            const bool sat = satisfied(net, c, x);
            if (net.is_hard(c)) { ok = ok && sat; continue; }
            if (!sat) continue;
            if (shares[c].param >= 0) add_feature(f, shares[c].param, shares[c].scale);
            else fixed += shares[c].fixed;
          }
          cond.allowed.push_back(ok ? 1 : 0);
          cond.fixed.push_back(fixed);
          cond.feats.push_back(std::move(f));
        }
        if (!block) cond.observed = world[atoms[0]];
        for (AtomId a : atoms) x[a] = world[a];
        out.push_back(std::move(cond));
      }
    }
  }
  return out;
}

// Pseudo-log-likelihood of the tabulated conditionals and its gradient.
double pll(const std::vector<Conditional>& conds, std::span<const double> w, std::vector<double>& grad) {
  double total = 0.0;
  std::vector<double> s, p;
  for (const auto& c : conds) {
    const std::size_t nv = c.allowed.size();
    s.assign(nv, -std::numeric_limits<double>::infinity());
    double mx = -std::numeric_limits<double>::infinity();
    for (std::size_t u = 0; u < nv; ++u) {
      if (!c.allowed[u]) continue;
      s[u] = c.fixed[u];
      for (const auto& [j, v] : c.feats[u]) s[u] += w[j] * v;
      mx = std::max(mx, s[u]);
    }
    double z = 0.0;
    p.assign(nv, 0.0);
    for (std::size_t u = 0; u < nv; ++u)
      if (c.allowed[u]) z += (p[u] = std::exp(s[u] - mx));
    total += c.count * (s[c.observed] - mx - std::log(z));
    for (const auto& [j, v] : c.feats[c.observed]) grad[j] += c.count * v;
    for (std::size_t u = 0; u < nv; ++u)
      for (const auto& [j, v] : c.feats[u]) grad[j] -= c.count * v * p[u] / z;
  }
  return total;
}

// The network with clause weights from the parameters (and no constant). Clause c of the
// result is clause c of `net`: a clause whose weight comes out exactly 0 is kept with the
// smallest positive weight (exp of it is 1: no factor), since its expected count is still
// part of the gradient.
GroundNetwork reweighted(const GroundNetwork& net, const WeightTying& tying, std::span<const double> w) {
  GroundNetwork out;
  out.add_atoms(net.num_atoms());
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) out.add_exactly_one(net.block(b));
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    if (net.is_hard(c)) { out.add_hard_clause(net.clause(c), net.origin(c)); continue; }
    const Share s = share_of(net, c, tying);
    const double wc = s.param >= 0 ? w[s.param] * s.scale : s.fixed;
    out.add_clause(net.clause(c), wc != 0.0 ? wc : std::numeric_limits<double>::denorm_min(), net.origin(c));
  }
  if (out.num_clauses() != net.num_clauses())
    throw MlnError("weight learning: the training network has duplicate or tautological clauses");
  return out;
}

// One training network for the conditional log-likelihood: its worlds' satisfied-clause
// counts per parameter, and the learned clauses with their parameter and scale.
struct CllSet {
  const GroundNetwork* net;
  double worlds = 0.0;
  std::vector<double> counts;  // per param: sum over worlds of scaled satisfied-clause counts
  double fixed = 0.0;          // sum over worlds of satisfied fixed soft weights
  std::vector<std::pair<std::int32_t, Share>> learned;  // (clause, share) with share.param >= 0
};

std::vector<CllSet> tabulate_cll(std::span<const TrainingSet> data, const WeightTying& tying, double& worlds) {
  std::vector<CllSet> sets;
  worlds = 0.0;
  for (std::size_t si = 0; si < data.size(); ++si) {
    const GroundNetwork& net = data[si].network;
    CllSet s{&net, 0.0, std::vector<double>(static_cast<std::size_t>(tying.num_params), 0.0), 0.0, {}};
    for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
      const Share sh = share_of(net, c, tying);
      if (sh.param >= 0) s.learned.push_back({c, sh});
    }
    for (auto& [x, count] : merge_worlds(data[si], si)) {
      s.worlds += count;
      for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
        if (net.is_hard(c) || !satisfied(net, c, x)) continue;
        const Share sh = share_of(net, c, tying);
        if (sh.param >= 0) s.counts[sh.param] += count * sh.scale;
        else s.fixed += count * sh.fixed;
      }
    }
    worlds += s.worlds;
    sets.push_back(std::move(s));
  }
  return sets;
}

// Conditional log-likelihood sum_worlds [sum_c w_c n_c(x) - log Z(w)] and its exact
// gradient: observed counts minus expected counts, E[n_c] = P(clause c satisfied) from
// exact inference (junction tree or enumeration) on the reweighted network.
double cll(const std::vector<CllSet>& sets, const WeightTying& tying, std::span<const double> w, std::vector<double>& grad,
           const ExactOptions& exact = {}) {
  double total = 0.0;
  std::vector<double> prob;
  for (const auto& s : sets) {
    total += s.fixed;
    for (std::size_t j = 0; j < w.size(); ++j) {
      total += w[j] * s.counts[j];
      grad[j] += s.counts[j];
    }
    total -= s.worlds * exact_clause_probabilities(reweighted(*s.net, tying, w), prob, exact).log_z;
    for (const auto& [c, sh] : s.learned) grad[sh.param] -= s.worlds * sh.scale * prob[c];
  }
  return total;
}

// Which expectations the conditional likelihood uses (LearnOptions::expectations): fills
// r.gradient (the exact solvers' summary) or r.sampled / r.too_large_*; returns r.sampled.
bool choose_expectations(std::span<const TrainingSet> data, const LearnOptions& o, LearnResult& r) {
  r.sampled = o.expectations == Expectations::Sampled;
  if (r.sampled) return true;
  ExactSummary summary;
  for (std::size_t si = 0; si < data.size() && r.too_large_set < 0; ++si) {
    const GroundNetwork& net = data[si].network;
    for (const auto& comp : split_components(net)) {
      const ExactPlan plan = plan_exact(net, comp, o.exact);
      if (plan.solver != ExactPlan::Solver::TooLarge) {
        summary.add(plan);
        continue;
      }
      if (o.expectations == Expectations::Exact)
        throw MlnError("training set " + std::to_string(si + 1) + ": " + too_large_message(net, comp, o.exact));
      r.too_large_set = static_cast<std::int32_t>(si);
      r.too_large_reason = "a component of " + std::to_string(comp.atoms.size()) + " free atoms (" +
                           std::to_string(static_cast<long long>(std::ceil(plan.bits))) +
                           " bits of state) that neither enumeration nor variable elimination fits";
      break;
    }
  }
  r.sampled = r.too_large_set >= 0;
  if (!r.sampled) r.gradient = "exact gradient (" + summary.describe() + ")";
  return r.sampled;
}

// The per-world mean and variance of each parameter's scaled satisfied-clause count over
// MC-SAT samples of one set's reweighted network.
void sampled_moments(const CllSet& s, const WeightTying& tying, std::span<const double> w, McSatOptions mo,
                     std::vector<double>& mean, std::vector<double>& var) {
  const GroundNetwork net = reweighted(*s.net, tying, w);
  const std::size_t np = w.size();
  std::vector<double> n(np), sum(np, 0.0), sq(np, 0.0);
  double count = 0.0;
  mo.on_sample = [&](std::span<const std::uint8_t> x) {
    std::fill(n.begin(), n.end(), 0.0);
    for (const auto& [c, sh] : s.learned)
      if (satisfied(net, c, x)) n[sh.param] += sh.scale;
    for (std::size_t j = 0; j < np; ++j) {
      sum[j] += n[j];
      sq[j] += n[j] * n[j];
    }
    count += 1.0;
  };
  mc_sat(net, mo);
  if (count <= 0.0) throw MlnError("weight learning: MC-SAT drew no samples");
  mean.assign(np, 0.0);
  var.assign(np, 0.0);
  for (std::size_t j = 0; j < np; ++j) {
    mean[j] = sum[j] / count;
    var[j] = std::max(0.0, sq[j] / count - mean[j] * mean[j]);
  }
}

// The sampled path's damped diagonal Newton ascent (weight_learning.h), Polyak-averaged.
void sampled_ascent(const std::vector<CllSet>& sets, const WeightTying& tying, std::vector<double> w, double worlds,
                    const LearnOptions& o, LearnResult& r) {
  const std::size_t np = w.size();
  const double inv_var = 1.0 / (o.prior_sigma * o.prior_sigma);
  const std::int32_t iterations = std::max<std::int32_t>(1, o.sampled_iterations);
  const std::int32_t half = iterations / 2;
  std::vector<double> g(np), h(np), hbar(np), mean, var, avg(np, 0.0);
  McSatOptions mo;
  mo.samples = o.samples;
  mo.burn_in = o.burn_in;
  for (std::int32_t t = 1; t <= iterations; ++t) {
    std::fill(g.begin(), g.end(), 0.0);
    std::fill(h.begin(), h.end(), 0.0);
    mo.seed = o.seed + static_cast<std::uint64_t>(t);
    for (const auto& s : sets) {
      sampled_moments(s, tying, w, mo, mean, var);
      for (std::size_t j = 0; j < np; ++j) {
        g[j] += s.counts[j] - s.worlds * mean[j];
        h[j] += s.worlds * var[j];
      }
    }
    const double eta = 1.0 / std::sqrt(static_cast<double>(t));
    for (std::size_t j = 0; j < np; ++j) {
      const double gj = (g[j] - w[j] * inv_var) / worlds, hj = (h[j] + inv_var) / worlds;
      if (t == 1) hbar[j] = hj;
      // The curvature of earlier iterations: dividing by this iteration's own sample
      // variance would correlate step and noise (a run with few violations of a clause
      // has both a low expected-count gap and a small variance), biasing the weight down.
      w[j] += eta * std::clamp(gj / hbar[j], -1.0, 1.0);
      hbar[j] = 0.8 * hbar[j] + 0.2 * hj;
      if (t > half) avg[j] += w[j];
    }
  }
  for (double& x : avg) x /= static_cast<double>(iterations - half);
  r.params = std::move(avg);
  r.iterations = iterations;
  r.converged = false;
  r.objective = std::numeric_limits<double>::quiet_NaN();
  r.gradient = "sampled expectations (MC-SAT, " + std::to_string(o.samples) + " samples, " +
               std::to_string(iterations) + " diagonal Newton iterations)";
}

}  // namespace

double conditional_log_likelihood(std::span<const TrainingSet> data, const WeightTying& tying,
                                  std::span<const double> params, std::vector<double>& gradient) {
  double worlds = 0.0;
  const auto sets = tabulate_cll(data, tying, worlds);
  gradient.assign(static_cast<std::size_t>(tying.num_params), 0.0);
  return cll(sets, tying, params, gradient);
}

LearnResult learn_weights(std::span<const TrainingSet> data, const WeightTying& tying, std::vector<double> initial,
                          const LearnOptions& options) {
  const auto np = static_cast<std::size_t>(tying.num_params);
  if (initial.size() != np) initial.assign(np, 0.0);
  double worlds = 0.0;
  std::function<double(std::span<const double>, std::vector<double>&)> data_term;
  std::vector<Conditional> conds;
  std::vector<CllSet> sets;
  if (options.objective == Objective::PseudoLikelihood) {
    conds = tabulate_pll(data, tying, worlds);
    data_term = [&](std::span<const double> w, std::vector<double>& g) { return pll(conds, w, g); };
  } else {
    sets = tabulate_cll(data, tying, worlds);
    data_term = [&](std::span<const double> w, std::vector<double>& g) { return cll(sets, tying, w, g, options.exact); };
  }
  if (worlds <= 0.0) throw MlnError("weight learning: no training worlds");
  LearnResult r;
  if (options.objective == Objective::ConditionalLikelihood && choose_expectations(data, options, r)) {
    if (options.samples <= 0) throw MlnError("weight learning: the sampled expectations need at least one sample");
    sampled_ascent(sets, tying, std::move(initial), worlds, options, r);
    return r;
  }
  const double inv_var = 1.0 / (options.prior_sigma * options.prior_sigma);
  // The objective per world: (data term - prior) / worlds, and its gradient.
  auto eval = [&](std::span<const double> w, std::vector<double>& g) {
    g.assign(np, 0.0);
    double f = data_term(w, g);
    for (std::size_t j = 0; j < np; ++j) {
      f -= 0.5 * w[j] * w[j] * inv_var;
      g[j] -= w[j] * inv_var;
      g[j] /= worlds;
    }
    return f / worlds;
  };
  std::vector<double> w = std::move(initial), g, wn, gn;
  double f = eval(w, g);
  double step = 1.0;
  const double tol = options.tolerance;
  for (r.iterations = 0; r.iterations < options.max_iterations; ++r.iterations) {
    double gmax = 0.0, gg = 0.0;
    for (double x : g) { gmax = std::max(gmax, std::abs(x)); gg += x * x; }
    if (gmax < tol) { r.converged = true; break; }
    double fn = f;
    double t = step;
    while (true) {
      wn = w;
      for (std::size_t j = 0; j < np; ++j) wn[j] += t * g[j];
      fn = eval(wn, gn);
      if (fn >= f + 1e-4 * t * gg) break;
      t *= 0.5;
      if (t < 1e-16) break;
    }
    if (t < 1e-16) break;  // no ascent possible: at the optimum up to rounding
    double ss = 0.0, sy = 0.0;
    for (std::size_t j = 0; j < np; ++j) {
      const double sj = wn[j] - w[j], yj = g[j] - gn[j];
      ss += sj * sj;
      sy += sj * yj;
    }
    step = sy > 0.0 ? std::clamp(ss / sy, 1e-8, 1e8) : t * 2.0;
    w.swap(wn);
    g.swap(gn);
    f = fn;
  }
  r.params = w;
  r.objective = f;
  return r;
}

}  // namespace ksmc::runtime::mln
