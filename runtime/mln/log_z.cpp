#include "runtime/mln/log_z.h"

#include <cmath>
#include <limits>
#include <vector>

#include "runtime/mln/components.h"
#include "runtime/io/cancel.h"
#include "runtime/mln/error.h"
#include "runtime/mln/local_state.h"

namespace ksmc::runtime::mln {

std::pair<double, double> ais_log_z(const GroundNetwork& net, const LogZOptions& options, std::uint64_t seed) {
  const Occurrences occ = build_occurrences(net);
  LocalState st(net, occ);
  Rng rng(seed);
  const VarList vars = make_var_list(net);
  double log_z0 = static_cast<double>(vars.atoms.size()) * std::log(2.0);
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) log_z0 += std::log(static_cast<double>(net.block(b).size()));
  double positive = 0.0;  // sum of w > 0: log-weight of a feasible state = positive - soft_cost
  for (std::int32_t c = 0; c < net.num_clauses(); ++c)
    if (!net.is_hard(c) && net.weight(c) > 0.0) positive += net.weight(c);

  const std::int32_t T = std::max<std::int32_t>(1, options.temperatures);
  const double H = options.hard_penalty;
  std::vector<double> logw;
  std::vector<double> probs;
  for (std::int32_t chain = 0; chain < std::max<std::int32_t>(1, options.chains); ++chain) {
    st.randomize(rng);  // exact sample of f_0
    double lw = 0.0;
    for (std::int32_t t = 1; t <= T; ++t) {
      io::throw_if_cancelled("estimating log Z");
      const double beta_prev = static_cast<double>(t - 1) / T;
      const double beta = static_cast<double>(t) / T;
      lw -= (beta - beta_prev) * (st.soft_cost() + H * st.hard_bad());
      // One Gibbs sweep leaving f_t invariant.
      for (AtomId a : vars.atoms) {
        const Delta d = st.flip_delta(a);
        const double dlog = -beta * (d.soft + H * d.hard);
        if (rng.uniform() < 1.0 / (1.0 + std::exp(-dlog))) st.flip(a);
      }
      for (std::int32_t b = 0; b < vars.num_blocks; ++b) {
        const auto atoms = net.block(b);
        probs.resize(atoms.size());
        double mx = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < atoms.size(); ++i) {
          const Delta d = st.move_delta(b, atoms[i]);
          probs[i] = -beta * (d.soft + H * d.hard);
          mx = std::max(mx, probs[i]);
        }
        double z = 0.0;
        for (auto& p : probs) z += (p = std::exp(p - mx));
        double u = rng.uniform() * z;
        std::size_t pick = 0;
        for (; pick + 1 < atoms.size() && u >= probs[pick]; ++pick) u -= probs[pick];
        st.move(b, atoms[pick]);
      }
      if ((t & 63) == 0) st.refresh_cost();
    }
    if (st.hard_bad() == 0) logw.push_back(lw);
  }
  if (logw.empty()) {
    throw MlnError("log Z estimate: no annealing chain ended in a state satisfying the hard constraints (" +
                   std::to_string(options.chains) + " chains); raise hard_penalty or temperatures");
  }
  const double n = std::max<std::int32_t>(1, options.chains);  // infeasible chains count as weight 0
  double mx = -std::numeric_limits<double>::infinity();
  for (double x : logw) mx = std::max(mx, x);
  double mean = 0.0, sq = 0.0;
  for (double x : logw) {
    const double w = std::exp(x - mx);
    mean += w;
    sq += w * w;
  }
  mean /= n;
  sq /= n;
  const double var = std::max(0.0, sq - mean * mean);
  const double se = std::sqrt(var / n) / mean;
  return {log_z0 + positive + mx + std::log(mean), se};
}

LogZResult log_partition(const GroundNetwork& net, const LogZOptions& options) {
  LogZResult r;
  r.log_z = net.constant();
  double var = 0.0;
  const auto comps = split_components(net);
  std::vector<Component> small;
  std::vector<ExactPlan> plans;
  std::vector<double> marginals(static_cast<std::size_t>(net.num_atoms()));
  for (std::size_t i = 0; i < comps.size(); ++i) {
    const auto& comp = comps[i];
    if (!options.force_ais) {
      auto plan = plan_exact(net, comp, options.exact);
      if (plan.solver != ExactPlan::Solver::TooLarge) {
        small.push_back(comp);
        plans.push_back(std::move(plan));
        continue;
      }
    }
    const auto [lz, se] = ais_log_z(extract_component(net, comp), options, options.seed * 1000003ULL + i);
    r.log_z += lz;
    var += se * se;
    r.exact = false;
    ++r.estimated_components;
  }
  r.log_z += solve_components(net, small, plans, marginals);
  r.std_error = std::sqrt(var);
  return r;
}

}  // namespace ksmc::runtime::mln
