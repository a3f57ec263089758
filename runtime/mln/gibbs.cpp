#include "runtime/mln/gibbs.h"

#include <cmath>
#include <vector>

#include "runtime/mln/local_state.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::mln {

InferenceResult gibbs_sampling(const GroundNetwork& net, const GibbsOptions& options) {
  const Occurrences occ = build_occurrences(net);
  Rng rng(options.seed);
  LocalState st(net, occ);
  st.assign(find_feasible_state(net, occ, rng));
  const VarList vars = make_var_list(net);
  InferenceResult r;
  r.method = "gibbs";
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  std::vector<double> probs;
  const std::int64_t total = options.burn_in + options.samples;
  for (std::int64_t sweep = 0; sweep < total; ++sweep) {
    const bool record = sweep >= options.burn_in;
    for (AtomId a : vars.atoms) {
      const Delta d = st.flip_delta(a);
      // P(flip) = w(flipped) / (w(now) + w(flipped)); log-weight change = -d.soft.
      const double p_flip = d.hard > 0 ? 0.0 : 1.0 / (1.0 + std::exp(d.soft));
      const double p_true = st.value(a) ? 1.0 - p_flip : p_flip;
      if (rng.uniform() < p_flip) st.flip(a);
      if (record) r.marginals[a] += options.rao_blackwell ? p_true : st.value(a);
    }
    for (std::int32_t b = 0; b < vars.num_blocks; ++b) {
      const auto atoms = net.block(b);
      probs.resize(atoms.size());
      double mx = -1e300;
      for (std::size_t i = 0; i < atoms.size(); ++i) {
        const Delta d = st.move_delta(b, atoms[i]);
        probs[i] = d.hard > 0 ? -1e300 : -d.soft;
        mx = std::max(mx, probs[i]);
      }
      double z = 0.0;
      for (auto& p : probs) {
        p = p <= -1e299 ? 0.0 : std::exp(p - mx);
        z += p;
      }
      double u = rng.uniform() * z;
      std::size_t pick = atoms.size() - 1;
      for (std::size_t i = 0; i < atoms.size(); ++i) {
        if (probs[i] > 0.0 && u < probs[i]) { pick = i; break; }
        u -= probs[i];
      }
      while (probs[pick] <= 0.0) --pick;  // rounding guard: never choose an infeasible value
      st.move(b, atoms[pick]);
      if (record) {
        for (std::size_t i = 0; i < atoms.size(); ++i)
          r.marginals[atoms[i]] += options.rao_blackwell ? probs[i] / z : (i == pick ? 1.0 : 0.0);
      }
    }
    if ((sweep & 255) == 255) st.refresh_cost();
    if (record && options.on_sample) options.on_sample(st.values());
  }
  if (options.samples > 0)
    for (auto& m : r.marginals) m /= static_cast<double>(options.samples);
  r.samples = options.samples;
  return r;
}

}  // namespace ksmc::runtime::mln
