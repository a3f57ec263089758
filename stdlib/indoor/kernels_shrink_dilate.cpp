// SHRINK / DILATE (seed §3.5.2): unit drawn by b_r (eq. 3.21), wall by v_w (eq. 3.22), shifted
// parallel to itself by a zero-mean Gaussian amount whose sign is the kernel's: SHRINK moves
// the wall inward, DILATE outward (each a half-normal of scale shift_sigma). The reverse of
// SHRINK(wall j, -d) is DILATE(wall j, +d) on the changed unit.
// Doors: a unit with doors may change when each of its doors still lies on a wall of the changed
// rectangle (door_wall_distance within door_snap, the rule ALLOCATE attaches by); the doors stay
// as they are. Every door lies on a wall of its units in any world the kernels reach, so the
// reverse move passes the same test and the proposal densities are those of the wall shift.
// Before, a unit with a door was frozen for SHRINK / DILATE (its shape could not be repaired
// once ALLOCATE or SPLIT had given it a door).
#include <cmath>

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor::kernels {

namespace {

std::optional<OrientedRect> shifted(const Context& c, const OrientedRect& r, int wall, double delta) {
  const Box b = shift_box_wall(own_box(r), wall, delta);
  if (b.width() < c.p.min_size || b.height() < c.p.min_size) return std::nullopt;
  return rect_from_box(b, Frame(r.theta));
}

double log_choice(const Context& c, const World& w, UnitId id, int wall, double delta) {
  const auto i = unit_index(w, id);
  if (!i) return kNegInf;
  const auto v = wall_change_weights(c, w.units()[*i]);
  // Half-normal density of |delta|: 2 * N(|delta|; 0, sigma).
  return log_normalized(unit_change_weights(c, w), *i) + log_normalized(v, static_cast<std::size_t>(wall)) +
         std::log(2.0) + log_normal_pdf(std::abs(delta), c.p.shift_sigma);
}

// Every door of unit `id` lies on a wall of `r`.
bool doors_stay(const Context& c, const World& w, UnitId id, const OrientedRect& r) {
  for (const Door& d : w.doors())
    if ((d.unit_a == id || d.unit_b == id) && !(door_wall_distance(c, r, d.a, d.b) <= c.p.door_snap)) return false;
  return true;
}

}  // namespace

std::optional<Forward> propose_shift(KernelKind kind, const Context& c, const World& w, Rng& rng) {
  const auto b = unit_change_weights(c, w);
  const auto i = draw_weighted(b, rng);
  if (!i) return std::nullopt;
  const Unit& u = w.units()[*i];
  const auto v = wall_change_weights(c, u);
  const auto j = draw_weighted(v, rng);
  if (!j) return std::nullopt;
  const double mag = std::abs(std::normal_distribution<double>(0.0, c.p.shift_sigma)(rng));
  if (!(mag > 0.0)) return std::nullopt;
  const double delta = kind == KernelKind::Shrink ? -mag : mag;
  const int wall = static_cast<int>(*j);
  const auto r = shifted(c, u.rect, wall, delta);
  if (!r || !doors_stay(c, w, u.id, *r)) return std::nullopt;
  Forward f;
  f.move.kind = kind;
  f.move.units.push_back({u.id, u, c.ev.make_unit(u.id, *r, u.lut_class)});
  f.move.detail.wall = wall;
  f.move.detail.delta = delta;
  f.log_q = log_normalized(b, *i) + log_normalized(v, *j) + std::log(2.0) +
            log_normal_pdf(mag, c.p.shift_sigma);
  return f;
}

double log_q_shift(KernelKind kind, const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (s.modified.size() != 1 || !s.added.empty() || !s.removed.empty() || !m.doors.empty()) return kNegInf;
  const int wall = m.detail.wall;
  const double delta = m.detail.delta;
  if (wall < 0 || wall > 3) return kNegInf;
  if ((kind == KernelKind::Shrink && !(delta < 0.0)) || (kind == KernelKind::Dilate && !(delta > 0.0)))
    return kNegInf;
  const UnitChange& ch = *s.modified[0];
  if (!unit_matches(c, w, ch.id, ch.before->rect)) return kNegInf;
  const auto r = shifted(c, w.find_unit(ch.id)->rect, wall, delta);
  if (!r || !same_rect(*r, ch.after->rect, c.p.coincide) || !doors_stay(c, w, ch.id, *r)) return kNegInf;
  return log_choice(c, w, ch.id, wall, delta);
}

}  // namespace ksmc::stdlib::indoor::kernels
