#include "stdlib/indoor/prior.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "stdlib/indoor/geometry.h"

namespace ksmc::stdlib::indoor {

void WeakPriorParams::validate() const {
  if (!(psi1 > 0.0 && psi1 < 1.0)) throw std::invalid_argument("weak prior: psi1 must be in (0,1), got " + std::to_string(psi1));
  if (!(psi2 > 0.0 && psi2 < 1.0)) throw std::invalid_argument("weak prior: psi2 must be in (0,1), got " + std::to_string(psi2));
  if (!(angle_tolerance >= 0.0)) throw std::invalid_argument("weak prior: angle_tolerance must be >= 0");
  if (!(adjacency_distance >= 0.0)) throw std::invalid_argument("weak prior: adjacency_distance must be >= 0");
}

namespace {

double cross(Point2 o, Point2 a, Point2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double point_segment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, {a.x + t * dx, a.y + t * dy});
}

double segment_distance(Point2 a, Point2 b, Point2 c, Point2 d) {
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0)
    return 0.0;
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                   point_segment(d, a, b)});
}

}  // namespace

int misaligned_wall_pairs(const Unit& a, const Unit& b, const WeakPriorParams& p) {
  if (angle_off_quarter(a.rect.theta - b.rect.theta) <= p.angle_tolerance) return 0;
  const double ra = 0.5 * std::hypot(a.rect.w, a.rect.h), rb = 0.5 * std::hypot(b.rect.w, b.rect.h);
  if (distance({a.rect.cx, a.rect.cy}, {b.rect.cx, b.rect.cy}) > ra + rb + p.adjacency_distance) return 0;
  const auto ca = a.rect.corners(), cb = b.rect.corners();
  int n = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (segment_distance(ca[static_cast<std::size_t>(i)], ca[static_cast<std::size_t>((i + 1) % 4)],
                           cb[static_cast<std::size_t>(j)], cb[static_cast<std::size_t>((j + 1) % 4)]) <=
          p.adjacency_distance)
        ++n;
  return n;
}

std::int64_t misaligned_pairs_involving(const World& world, std::span<const UnitId> ids,
                                        const WeakPriorParams& p) {
  std::int64_t s = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Unit* a = world.find_unit(ids[i]);
    if (!a) continue;
    for (const Unit& b : world.units()) {
      if (b.id == a->id) continue;
      // A pair of two listed units is counted once (by the one listed first).
      const auto pos = std::find(ids.begin(), ids.end(), b.id);
      if (pos != ids.end() && static_cast<std::size_t>(pos - ids.begin()) < i) continue;
      s += misaligned_wall_pairs(*a, b, p);
    }
  }
  return s;
}

std::int64_t misaligned_pairs_total(const World& world, const WeakPriorParams& p) {
  std::int64_t s = 0;
  const auto u = world.units();
  for (std::size_t i = 0; i < u.size(); ++i)
    for (std::size_t j = i + 1; j < u.size(); ++j) s += misaligned_wall_pairs(u[i], u[j], p);
  return s;
}

double weak_log_prior(std::int64_t theta, std::int64_t overlap, const WeakPriorParams& p) {
  return static_cast<double>(theta) * std::log(p.psi1) + static_cast<double>(overlap) * std::log(p.psi2);
}

}  // namespace ksmc::stdlib::indoor
