#include "runtime/mln/mcsat.h"

#include <cmath>
#include <vector>

#include "runtime/io/cancel.h"
#include "runtime/mln/local_state.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::mln {
namespace {

// One simulated-annealing move under the current (count) objective.
void sa_step(LocalState& st, const VarList& vars, Rng& rng, double temperature) {
  const GroundNetwork& net = st.network();
  const auto k = static_cast<std::int32_t>(rng.below(static_cast<std::uint32_t>(vars.size())));
  const auto n_atoms = static_cast<std::int32_t>(vars.atoms.size());
  if (k < n_atoms) {
    const AtomId a = vars.atoms[k];
    const Delta d = st.flip_delta(a);
    if (d.soft <= 0.0 || rng.uniform() < std::exp(-d.soft / temperature)) st.flip(a);
    return;
  }
  const std::int32_t b = k - n_atoms;
  const auto atoms = net.block(b);
  const AtomId to = atoms[rng.below(static_cast<std::uint32_t>(atoms.size()))];
  if (to == st.block_true(b)) return;
  const Delta d = st.move_delta(b, to);
  if (d.soft <= 0.0 || rng.uniform() < std::exp(-d.soft / temperature)) st.move(b, to);
}

}  // namespace

InferenceResult mc_sat(const GroundNetwork& net, const McSatOptions& options) {
  const Occurrences occ = build_occurrences(net);
  Rng rng(options.seed);
  LocalState st(net, occ);
  st.assign(find_feasible_state(net, occ, rng));
  const VarList vars = make_var_list(net);
  const std::int32_t m = net.num_clauses();
  std::vector<double> cost(static_cast<std::size_t>(m));
  std::vector<std::uint8_t> want(static_cast<std::size_t>(m));
  std::vector<double> keep_prob(static_cast<std::size_t>(m));
  for (std::int32_t c = 0; c < m; ++c) {
    want[c] = (net.is_hard(c) || net.weight(c) > 0.0) ? 1 : 0;
    keep_prob[c] = net.is_hard(c) ? 1.0 : -std::expm1(-std::abs(net.weight(c)));
  }
  const std::int32_t steps =
      options.sample_sat_steps > 0 ? options.sample_sat_steps : std::max<std::int32_t>(20, 4 * vars.size());
  std::vector<std::uint8_t> saved;
  InferenceResult r;
  r.method = "mcsat";
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  const std::int64_t total = options.burn_in + options.samples;
  for (std::int64_t it = 0; it < total; ++it) {
    io::throw_if_cancelled("MC-SAT");
    // The slice: clauses the current state gets right, each kept with prob. 1 - e^-|w|.
    for (std::int32_t c = 0; c < m; ++c) {
      const bool right = (st.sat_count(c) > 0) == (want[c] != 0);
      cost[c] = (right && (keep_prob[c] >= 1.0 || rng.uniform() < keep_prob[c])) ? 1.0 : 0.0;
    }
    st.set_objective(cost, want);
    saved = st.values();
    // SampleSAT from the current state (which satisfies the slice).
    for (std::int32_t s = 0; s < steps; ++s) {
      if ((s & 1023) == 1023) io::throw_if_cancelled("MC-SAT");
      if (st.num_bad() == 0 || rng.uniform() < options.sa_probability) sa_step(st, vars, rng, options.temperature);
      else walksat_step(st, rng, options.walk_noise);
    }
    for (std::int32_t s = 0; s < 10 * steps && st.num_bad() > 0; ++s) walksat_step(st, rng, options.walk_noise);
    if (st.num_bad() > 0) st.assign(saved);  // failed: stay (still inside the slice)
    if (it >= options.burn_in) {
      const auto& v = st.values();
      for (std::size_t a = 0; a < v.size(); ++a) r.marginals[a] += v[a];
      if (options.on_sample) options.on_sample(v);
    }
  }
  if (options.samples > 0)
    for (auto& x : r.marginals) x /= static_cast<double>(options.samples);
  r.samples = options.samples;
  return r;
}

}  // namespace ksmc::runtime::mln
