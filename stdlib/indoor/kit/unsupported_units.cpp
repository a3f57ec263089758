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

Move removal(const World& w, UnitId id) {
  Move m;
  m.kind = KernelKind::Remove;
  m.units.push_back({id, *w.find_unit(id), std::nullopt});
  return m;
}

}  // namespace ksmc::stdlib::indoor::kit
