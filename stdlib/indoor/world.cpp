#include "stdlib/indoor/world.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ksmc::stdlib::indoor {

double Unit::weight() const {
  return *std::min_element(wall_weight.begin(), wall_weight.end());
}

KernelKind reverse_of(KernelKind k) {
  switch (k) {
    case KernelKind::Add: return KernelKind::Remove;
    case KernelKind::Remove: return KernelKind::Add;
    case KernelKind::Split: return KernelKind::Merge;
    case KernelKind::Merge: return KernelKind::Split;
    case KernelKind::Shrink: return KernelKind::Dilate;
    case KernelKind::Dilate: return KernelKind::Shrink;
    case KernelKind::Allocate: return KernelKind::Delete;
    case KernelKind::Delete: return KernelKind::Allocate;
    case KernelKind::Interchange: return KernelKind::Interchange;
  }
  return k;
}

const char* kernel_name(KernelKind k) {
  switch (k) {
    case KernelKind::Add: return "birth";
    case KernelKind::Remove: return "death";
    case KernelKind::Split: return "split";
    case KernelKind::Merge: return "merge";
    case KernelKind::Shrink: return "shrink";
    case KernelKind::Dilate: return "dilate";
    case KernelKind::Allocate: return "allocate";
    case KernelKind::Delete: return "deallocate";
    case KernelKind::Interchange: return "interchange";
  }
  return "?";
}

Move Move::inverse() const {
  Move r;
  r.kind = reverse_of(kind);
  r.units.reserve(units.size());
  for (const auto& c : units) r.units.push_back({c.id, c.after, c.before});
  for (const auto& c : doors) r.doors.push_back({c.id, c.after, c.before});
  r.detail = detail;
  r.detail.delta = -detail.delta;
  return r;
}

namespace {

template <class T, class Id>
typename std::vector<T>::iterator lower(std::vector<T>& v, Id id) {
  return std::lower_bound(v.begin(), v.end(), id, [](const T& a, Id b) { return a.id < b; });
}

template <class T, class Id>
const T* find_sorted(const std::vector<T>& v, Id id) {
  auto it = std::lower_bound(v.begin(), v.end(), id, [](const T& a, Id b) { return a.id < b; });
  return (it != v.end() && it->id == id) ? &*it : nullptr;
}

// Exact equality: a move's 'before' must be the stored member, or the score would drift.
bool same_unit(const Unit& a, const Unit& b) {
  return a.id == b.id && a.rect.cx == b.rect.cx && a.rect.cy == b.rect.cy && a.rect.w == b.rect.w &&
         a.rect.h == b.rect.h && a.rect.theta == b.rect.theta && a.lut_class == b.lut_class;
}
bool same_door(const Door& a, const Door& b) {
  return a.id == b.id && a.unit_a == b.unit_a && a.unit_b == b.unit_b && a.a.x == b.a.x && a.a.y == b.a.y &&
         a.b.x == b.b.x && a.b.y == b.b.y;
}

[[noreturn]] void misfit(const char* what, std::uint32_t id) {
  throw std::logic_error(std::string("World::apply: ") + what + " " + std::to_string(id));
}

}  // namespace

const Unit* World::find_unit(UnitId id) const { return find_sorted(units_, id); }
const Door* World::find_door(DoorId id) const { return find_sorted(doors_, id); }

int World::door_count(UnitId id) const {
  int n = 0;
  for (const auto& d : doors_) n += (d.unit_a == id || d.unit_b == id) ? 1 : 0;
  return n;
}

void World::apply(const Move& m) {
  World w = *this;  // strong guarantee: *this is unchanged when the move does not fit
  w.apply_in_place(m);
  *this = std::move(w);
}

void World::apply_in_place(const Move& m) {
  // Removals first (doors, then units), then additions (units, then doors).
  for (const auto& c : m.doors) {
    if (!c.before) continue;
    auto it = lower(doors_, c.id);
    if (it == doors_.end() || it->id != c.id) misfit("door to change is missing:", c.id);
    if (!same_door(*it, *c.before)) misfit("door differs from the move's 'before' state:", c.id);
    doors_.erase(it);
  }
  for (const auto& c : m.units) {
    if (!c.before) continue;
    auto it = lower(units_, c.id);
    if (it == units_.end() || it->id != c.id) misfit("unit to change is missing:", c.id);
    if (!same_unit(*it, *c.before)) misfit("unit differs from the move's 'before' state:", c.id);
    units_.erase(it);
  }
  for (const auto& c : m.units) {
    if (!c.after) continue;
    if (c.after->id != c.id) misfit("unit change with mismatched id:", c.id);
    auto it = lower(units_, c.id);
    if (it != units_.end() && it->id == c.id) misfit("unit to add exists:", c.id);
    units_.insert(it, *c.after);
    next_unit_id_ = std::max(next_unit_id_, c.id + 1);
  }
  for (const auto& c : m.doors) {
    if (!c.after) continue;
    if (c.after->id != c.id) misfit("door change with mismatched id:", c.id);
    if (!find_unit(c.after->unit_a) || !find_unit(c.after->unit_b))
      misfit("door refers to an absent unit:", c.id);
    auto it = lower(doors_, c.id);
    if (it != doors_.end() && it->id == c.id) misfit("door to add exists:", c.id);
    doors_.insert(it, *c.after);
    next_door_id_ = std::max(next_door_id_, c.id + 1);
  }
  for (const auto& d : doors_) {
    if (!find_unit(d.unit_a) || !find_unit(d.unit_b))
      misfit("a removed unit still has door", d.id);
  }
}

World World::applied(const Move& m) const {
  World w = *this;
  w.apply(m);
  return w;
}

}  // namespace ksmc::stdlib::indoor
