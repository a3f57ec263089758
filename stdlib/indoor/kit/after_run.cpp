#include "stdlib/indoor/kit/after_run.h"

#include "stdlib/indoor/kit/merged_units.h"
#include "stdlib/indoor/kit/unsupported_units.h"

namespace ksmc::stdlib::indoor::kit {

AfterRunResult improve_after_run(IndoorModel& m) {
  AfterRunResult r;
  r.log_posterior_before = m.log_posterior();
  const MapEvidence& ev = *m.input().evidence;
  for (bool changed = true; changed;) {
    changed = false;
    const World& w = m.scored().world();
    for (const UnitId id : doorless_units(w))
      if (m.improve(removal(w, id))) {
        r.removed.push_back(id);
        changed = true;
        break;
      }
    if (changed) continue;
    for (const MergeCandidate& c : merge_candidates(w, m.input().grid))
      if (m.improve(merge_move(w, ev, c))) {
        r.merged.emplace_back(c.a, c.b);
        changed = true;
        break;
      }
  }
  r.log_posterior_after = m.log_posterior();
  return r;
}

}  // namespace ksmc::stdlib::indoor::kit
