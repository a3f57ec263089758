#include "stdlib/tabletop/perception/footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ksmc::stdlib::tabletop::perception {

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Turns (u, half) into the canonical form with the angle of u in [0, 90 deg).
void canonicalise(Rect2& r) {
  for (int k = 0; k < 4; ++k) {
    const double angle = std::atan2(r.u.y(), r.u.x());
    if (angle >= 0.0 && angle < 0.5 * 3.14159265358979323846 - 1e-12) return;
    r.u = Eigen::Vector2d(r.u.y(), -r.u.x());  // rotate by -90 deg: sides swap
    std::swap(r.half.x(), r.half.y());
  }
}

}  // namespace

bool rects_overlap(const Rect2& a, const Rect2& b, double slack) {
  const Eigen::Vector2d d = b.center - a.center;
  for (const Eigen::Vector2d& n : {a.u, a.v(), b.u, b.v()}) {
    const double ra = a.half.x() * std::abs(a.u.dot(n)) + a.half.y() * std::abs(a.v().dot(n));
    const double rb = b.half.x() * std::abs(b.u.dot(n)) + b.half.y() * std::abs(b.v().dot(n));
    if (std::abs(d.dot(n)) > ra + rb + 2.0 * slack) return false;
  }
  return true;
}

double quantile(std::vector<double>& values, double q) {
  std::sort(values.begin(), values.end());
  const double pos = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 1e-12) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 1e-12) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

namespace {

// The rectangle of `points`' hull extents along the hull edge direction (the sides' directions
// of all minimal rectangles; Freeman & Shapira 1975) with the least cost(points, rectangle);
// with `trim` > 0 each side is then pulled in to the trim / (1 - trim) quantile.
template <class Cost>
Rect2 best_rect(const std::vector<Eigen::Vector2d>& points, double trim, Cost cost) {
  Rect2 best;
  if (points.empty()) return best;
  const std::vector<Eigen::Vector2d> hull = convex_hull(points);
  double best_cost = std::numeric_limits<double>::infinity();
  auto try_direction = [&](const Eigen::Vector2d& u) {
    const Eigen::Vector2d v(-u.y(), u.x());
    double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
    for (const auto& q : hull) {
      lo_u = std::min(lo_u, q.dot(u)), hi_u = std::max(hi_u, q.dot(u));
      lo_v = std::min(lo_v, q.dot(v)), hi_v = std::max(hi_v, q.dot(v));
    }
    Rect2 r;
    r.u = u;
    r.half = 0.5 * Eigen::Vector2d(hi_u - lo_u, hi_v - lo_v);
    r.center = 0.5 * (lo_u + hi_u) * u + 0.5 * (lo_v + hi_v) * v;
    const double c = cost(r);
    if (c < best_cost - 1e-15) {
      best_cost = c;
      best = r;
    }
  };
  if (hull.size() < 2) {
    try_direction(Eigen::Vector2d::UnitX());
  } else {
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
      if (e.norm() > 0.0) try_direction(e.normalized());
    }
  }
  if (trim > 0.0 && points.size() >= 4) return rect_along(points, best.u, trim);
  canonicalise(best);
  return best;
}

}  // namespace

Rect2 rect_along(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& u, double trim) {
  Rect2 r;
  r.u = u.normalized();
  const Eigen::Vector2d v = r.v();
  std::vector<double> su, sv;
  su.reserve(points.size());
  sv.reserve(points.size());
  for (const auto& q : points) su.push_back(q.dot(r.u)), sv.push_back(q.dot(v));
  const double lu = quantile(su, trim), hu = quantile(su, 1.0 - trim);
  const double lv = quantile(sv, trim), hv = quantile(sv, 1.0 - trim);
  r.half = 0.5 * Eigen::Vector2d(hu - lu, hv - lv);
  r.center = 0.5 * (lu + hu) * r.u + 0.5 * (lv + hv) * v;
  canonicalise(r);
  return r;
}

Rect2 min_area_rect(const std::vector<Eigen::Vector2d>& points, double trim) {
  return best_rect(points, trim, [](const Rect2& r) { return r.area(); });
}

Obb upright_over(const Rect2& r, double bottom, double top, double inset) {
  Obb b;
  b.center = Eigen::Vector3d(r.center.x(), r.center.y(), 0.5 * (bottom + top));
  b.axes.col(0) = Eigen::Vector3d(r.u.x(), r.u.y(), 0.0);
  b.axes.col(1) = Eigen::Vector3d(r.v().x(), r.v().y(), 0.0);
  b.axes.col(2) = Eigen::Vector3d::UnitZ();
  b.half = Eigen::Vector3d(r.half.x() - inset, r.half.y() - inset, 0.5 * (top - bottom) - inset);
  return b;
}

Rect2 faces_rect(const std::vector<Eigen::Vector2d>& points, double trim) {
  return best_rect(points, trim, [&points](const Rect2& r) {
    double sum = 0.0;
    for (const auto& q : points) {
      const Eigen::Vector2d d = q - r.center;
      sum += std::min(r.half.x() - std::abs(d.dot(r.u)), r.half.y() - std::abs(d.dot(r.v())));
    }
    return sum;
  });
}

}  // namespace ksmc::stdlib::tabletop::perception
