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

runtime::mcmc::Snapshot without_unit(runtime::mcmc::Snapshot s, UnitId id) {
  auto& units = s["units"];
  units.erase(std::remove_if(units.begin(), units.end(),
                             [id](const runtime::mcmc::Snapshot& u) { return u.at("id").get<UnitId>() == id; }),
              units.end());
  return s;
}

}  // namespace ksmc::stdlib::indoor::kit
