#include "stdlib/indoor/kit/after_run.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

#include "stdlib/indoor/kit/merged_units.h"
#include "stdlib/indoor/kit/split_units.h"
#include "stdlib/indoor/kit/unsupported_units.h"

namespace ksmc::stdlib::indoor::kit {

namespace {

// The door widths the domain declares (all door sources pooled), cells; an empty range without.
std::pair<double, double> door_widths(const SharedInput& in) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const SourcePool& p : in.plan.pools)
    for (const auto& d : p.doors) {
      lo = std::min(lo, d.min_width / in.resolution);
      hi = std::max(hi, d.max_width / in.resolution);
    }
  return {lo, hi};
}

}  // namespace

AfterRunResult improve_after_run(IndoorModel& m) {
  AfterRunResult r;
  const auto [min_door, max_door] = door_widths(m.input());
  std::map<UnitId, std::vector<SplitCandidate>> cuts_of;
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
    if (changed) continue;
    // A unit's cuts depend on its rectangle alone, and the search never changes a unit's
    // rectangle (it removes units and adds new ones): they are found once per unit.
    std::vector<SplitCandidate> cuts;
    for (const Unit& u : w.units()) {
      auto it = cuts_of.find(u.id);
      if (it == cuts_of.end()) it = cuts_of.emplace(u.id, split_candidates(u, m.input().grid, min_door, max_door)).first;
      cuts.insert(cuts.end(), it->second.begin(), it->second.end());
    }
    sort_split_candidates(cuts);
    for (const SplitCandidate& c : cuts) {
      for (const bool with_door : {true, false}) {
        const auto move = split_move(w, ev, c, with_door);
        if (move && m.improve(*move)) {
          r.split.push_back(c.unit);
          changed = true;
          break;
        }
      }
      if (changed) break;
    }
  }
  r.log_posterior_after = m.log_posterior();
  return r;
}

}  // namespace ksmc::stdlib::indoor::kit
