#include "stdlib/indoor/kit/unsupported_units.h"

#include <algorithm>

namespace ksmc::stdlib::indoor::kit {

std::vector<UnitId> doorless_units(const World& w) {
  std::vector<const Unit*> found;
  for (const Unit& u : w.units())
    if (std::none_of(w.doors().begin(), w.doors().end(),
                     [&](const Door& d) { return d.unit_a == u.id || d.unit_b == u.id; }))
      found.push_back(&u);
  std::sort(found.begin(), found.end(), [](const Unit* a, const Unit* b) {
    return a->rect.area() != b->rect.area() ? a->rect.area() < b->rect.area() : a->id < b->id;
  });
  std::vector<UnitId> out;
  for (const Unit* u : found) out.push_back(u->id);
  return out;
}

RemovedUnits remove_unsupported_units(IndoorModel& m) {
  RemovedUnits r;
  r.log_posterior_before = m.log_posterior();
  double best = r.log_posterior_before;
  for (bool changed = true; changed;) {
    changed = false;
    const runtime::mcmc::Snapshot current = m.snapshot();
    for (const UnitId id : doorless_units(m.scored().world())) {
      runtime::mcmc::Snapshot without = current;
      auto& units = without["units"];
      units.erase(std::remove_if(units.begin(), units.end(),
                                 [id](const runtime::mcmc::Snapshot& u) { return u.at("id").get<UnitId>() == id; }),
                  units.end());
      m.restore(without);  // full rescoring of the world without the unit
      const double lp = m.log_posterior();
      if (lp > best) {
        best = lp;
        r.removed.push_back(id);
        changed = true;
        break;
      }
      m.restore(current);
    }
  }
  r.log_posterior_after = best;
  return r;
}

}  // namespace ksmc::stdlib::indoor::kit
