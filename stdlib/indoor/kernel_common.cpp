#include "stdlib/indoor/kernel_common.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ksmc::stdlib::indoor::kernels {

std::vector<double> unit_change_weights(const Context& c, const World& w) {
  std::vector<double> b;
  b.reserve(w.units().size());
  for (const Unit& u : w.units()) b.push_back(capped_inverse(u.weight(), c.p.h_b));
  return b;
}

std::array<double, 4> wall_change_weights(const Context& c, const Unit& u) {
  std::array<double, 4> v{};
  for (std::size_t j = 0; j < 4; ++j) v[j] = capped_inverse(u.wall_weight[j], c.p.h_v);
  return v;
}

namespace {
// a_r(s) = 1 / d(c_r, c_s), with the distance floored at one cell.
std::vector<double> partner_weights(const World& w, std::size_t r) {
  const auto units = w.units();
  std::vector<double> a(units.size(), 0.0);
  for (std::size_t s = 0; s < units.size(); ++s) {
    if (s == r) continue;
    const double d = distance({units[r].rect.cx, units[r].rect.cy}, {units[s].rect.cx, units[s].rect.cy});
    a[s] = 1.0 / std::max(d, 1.0);
  }
  return a;
}
}  // namespace

std::optional<std::size_t> unit_index(const World& w, UnitId id) {
  const auto units = w.units();
  for (std::size_t i = 0; i < units.size(); ++i)
    if (units[i].id == id) return i;
  return std::nullopt;
}

double log_pair_probability(const World& w, UnitId r, UnitId s) {
  const auto ir = unit_index(w, r), is = unit_index(w, s);
  if (!ir || !is || *ir == *is) return kNegInf;
  const double n = static_cast<double>(w.units().size());
  const auto ar = partner_weights(w, *ir), as = partner_weights(w, *is);
  const double p = (std::exp(log_normalized(ar, *is)) + std::exp(log_normalized(as, *ir))) / n;
  return p > 0.0 ? std::log(p) : kNegInf;
}

std::optional<std::pair<std::size_t, std::size_t>> draw_pair(const World& w, Rng& rng) {
  const auto n = w.units().size();
  if (n < 2) return std::nullopt;
  const auto r = static_cast<std::size_t>(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng));
  const auto a = partner_weights(w, r);
  const auto s = draw_weighted(a, rng);
  if (!s) return std::nullopt;
  return std::make_pair(r, *s);
}

bool unit_free(const Context& c, const World& w, UnitId id, const OrientedRect& r) {
  const Unit* u = w.find_unit(id);
  return u && same_rect(u->rect, r, c.p.coincide) && w.door_count(id) == 0;
}

bool unit_matches(const Context& c, const World& w, UnitId id, const OrientedRect& r) {
  const Unit* u = w.find_unit(id);
  return u && same_rect(u->rect, r, c.p.coincide);
}

double door_wall_distance(const Context& c, const OrientedRect& r, Point2 a, Point2 b) {
  const Point2 mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const double ang = std::atan2(b.y - a.y, b.x - a.x);
  const auto cs = r.corners();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < 4; ++j) {
    const Point2 p = cs[j], q = cs[(j + 1) % 4];
    const double wl = distance(p, q);
    if (!(wl > 0.0)) continue;
    double dang = std::fmod(std::abs(std::atan2(q.y - p.y, q.x - p.x) - ang), kPi);
    dang = std::min(dang, kPi - dang);
    if (dang > c.p.door_angle) continue;
    const double tx = (q.x - p.x) / wl, ty = (q.y - p.y) / wl;
    const double along = (mid.x - p.x) * tx + (mid.y - p.y) * ty;
    const double across = std::abs(-(mid.x - p.x) * ty + (mid.y - p.y) * tx);
    if (along < 0.0 || along > wl || across > c.p.door_snap) continue;
    best = std::min(best, across);
  }
  return best;
}

Shape shape_of(const Move& m) {
  Shape s;
  for (const auto& ch : m.units) {
    if (ch.before && ch.after) s.modified.push_back(&ch);
    else if (ch.before) s.removed.push_back(&ch);
    else if (ch.after) s.added.push_back(&ch);
  }
  return s;
}

double log_normal_pdf(double x, double sigma) {
  return -0.5 * (x / sigma) * (x / sigma) - std::log(sigma) - 0.5 * std::log(2.0 * kPi);
}

bool same_segment(const Context& c, Point2 a, Point2 b, Point2 p, Point2 q) {
  const double e = c.p.coincide;
  return (distance(a, p) <= e && distance(b, q) <= e) || (distance(a, q) <= e && distance(b, p) <= e);
}

}  // namespace ksmc::stdlib::indoor::kernels
