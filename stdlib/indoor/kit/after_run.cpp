#include "stdlib/indoor/kit/after_run.h"

#include "stdlib/indoor/kit/merged_units.h"
#include "stdlib/indoor/kit/unsupported_units.h"

namespace ksmc::stdlib::indoor::kit {

AfterRunResult improve_after_run(IndoorModel& m) {
  AfterRunResult r;
  r.log_posterior_before = m.log_posterior();
  double best = r.log_posterior_before;
  // true when `candidate` scores higher (it stays the state), else the state is put back.
  auto try_state = [&](const runtime::mcmc::Snapshot& current, const runtime::mcmc::Snapshot& candidate) {
    m.restore(candidate);
    const double lp = m.log_posterior();
    if (lp > best) {
      best = lp;
      return true;
    }
    m.restore(current);
    return false;
  };
  for (bool changed = true; changed;) {
    changed = false;
    const runtime::mcmc::Snapshot current = m.snapshot();
    const World& w = m.scored().world();
    const auto doorless = doorless_units(w);
    const auto merges = merge_candidates(w, m.input().grid);
    for (const UnitId id : doorless)
      if (try_state(current, without_unit(current, id))) {
        r.removed.push_back(id);
        changed = true;
        break;
      }
    if (changed) continue;
    for (const MergeCandidate& c : merges)
      if (try_state(current, with_merge(current, c))) {
        r.merged.emplace_back(c.a, c.b);
        changed = true;
        break;
      }
  }
  r.log_posterior_after = best;
  return r;
}

}  // namespace ksmc::stdlib::indoor::kit
