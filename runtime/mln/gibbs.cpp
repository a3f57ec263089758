#include "runtime/mln/gibbs.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include "runtime/io/cancel.h"
#include "runtime/mln/local_state.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::runtime::mln {
namespace {

// Groups of free (non-block) atoms tied by hard equivalences: a pair of hard clauses
// (l1 v l2) and (!l1 v !l2) forces l1 = !l2, so single-site moves can never change
// either atom. Such atoms are resampled jointly (all flipped together).
std::vector<std::vector<AtomId>> equivalence_groups(const GroundNetwork& net, const std::vector<AtomId>& atoms) {
  std::set<std::pair<Lit, Lit>> binary;
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    const auto l = net.clause(c);
    if (net.is_hard(c) && l.size() == 2) binary.emplace(l[0], l[1]);
  }
  std::vector<AtomId> parent(static_cast<std::size_t>(net.num_atoms()));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](AtomId x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [l1, l2] : binary) {
    const Lit n1 = l1 ^ 1, n2 = l2 ^ 1;
    if (!binary.count({std::min(n1, n2), std::max(n1, n2)})) continue;
    const AtomId a = lit_atom(l1), b = lit_atom(l2);
    if (net.block_of(a) >= 0 || net.block_of(b) >= 0) continue;
    const AtomId ra = find(a), rb = find(b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
  }
  std::vector<std::vector<AtomId>> groups;
  std::vector<std::int32_t> group_of(static_cast<std::size_t>(net.num_atoms()), -1);
  for (AtomId a : atoms) {
    const AtomId r = find(a);
    if (group_of[r] < 0) {
      group_of[r] = static_cast<std::int32_t>(groups.size());
      groups.emplace_back();
    }
    groups[group_of[r]].push_back(a);
  }
  return groups;
}

}  // namespace

InferenceResult gibbs_sampling(const GroundNetwork& net, const GibbsOptions& options) {
  const Occurrences occ = build_occurrences(net);
  Rng rng(options.seed);
  LocalState st(net, occ);
  st.assign(find_feasible_state(net, occ, rng));
  const VarList vars = make_var_list(net);
  const auto groups = equivalence_groups(net, vars.atoms);
  InferenceResult r;
  r.method = "gibbs";
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), 0.0);
  std::vector<double> probs;
  const std::int64_t total = options.burn_in + options.samples;
  for (std::int64_t sweep = 0; sweep < total; ++sweep) {
    io::throw_if_cancelled("Gibbs sampling");
    const bool record = sweep >= options.burn_in;
    for (const auto& group : groups) {
      Delta d;
      if (group.size() == 1) {
        d = st.flip_delta(group[0]);
      } else {  // flip the whole group, measure, and undo if not accepted below
        const std::int32_t h0 = st.hard_bad();
        const double s0 = st.soft_cost();
        for (AtomId a : group) st.flip(a);
        d.hard = st.hard_bad() - h0;
        d.soft = st.soft_cost() - s0;
        for (AtomId a : group) st.flip(a);
      }
      // P(flip) = w(flipped) / (w(now) + w(flipped)); log-weight change = -d.soft.
      const double p_flip = d.hard > 0 ? 0.0 : 1.0 / (1.0 + std::exp(d.soft));
      if (record && options.rao_blackwell)
        for (AtomId a : group) r.marginals[a] += st.value(a) ? 1.0 - p_flip : p_flip;
      if (rng.uniform() < p_flip)
        for (AtomId a : group) st.flip(a);
      if (record && !options.rao_blackwell)
        for (AtomId a : group) r.marginals[a] += st.value(a);
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
