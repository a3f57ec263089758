#include "stdlib/indoor/blocks/walls.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ksmc::stdlib::indoor::blocks {

GeomClass classify_unit(const OrientedRect& r, double resolution, double big_size_m, double big_ratio,
                        double corridor_width_m) {
  const double lo = std::min(std::abs(r.w), std::abs(r.h)) * resolution;
  const double hi = std::max(std::abs(r.w), std::abs(r.h)) * resolution;
  const bool elongated = lo <= 0.0 || hi / lo > big_ratio;
  if (elongated && lo <= corridor_width_m) return GeomClass::CorridorLike;  // long and narrow, any length
  if (hi > big_size_m) return GeomClass::HallLike;
  if (elongated) return GeomClass::CorridorLike;
  return GeomClass::RoomLike;
}

namespace {
struct Edge {
  Point2 p0, p1;
  double length, dx, dy;  // unit direction; length 0 (degenerate) is skipped
};
std::array<Edge, 4> edges_of(const OrientedRect& r) {
  const auto c = r.corners();
  std::array<Edge, 4> e;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point2 p0 = c[i], p1 = c[(i + 1) % 4];
    const double l = std::hypot(p1.x - p0.x, p1.y - p0.y);
    e[i] = {p0, p1, l, l > 0.0 ? (p1.x - p0.x) / l : 0.0, l > 0.0 ? (p1.y - p0.y) / l : 0.0};
  }
  return e;
}
}  // namespace

std::optional<WallPair> connecting_walls(const OrientedRect& a, const OrientedRect& b, double dilate_cells) {
  // Called for every unit pair of every proposal's semantic evaluation: each rectangle's
  // edges are measured once, not once per edge pair.
  const double max_gap = 2.0 * dilate_cells + 1.0;
  static const double sin_tol = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  // A pair below passes only if some point of b's edge lies within max_gap + (its length / 2)
  // * sin_tol of a's edge (the midpoint's distance plus the tilt over half the edge, at a
  // point whose projection falls on a's edge). So rectangles whose enclosing circles are
  // farther apart than that (plus a cell against rounding) share no wall: most pairs of a
  // large map, decided without their corners.
  if (dilate_cells >= 0.0) {
    const double reach = max_gap + 0.5 * std::max(std::abs(b.w), std::abs(b.h)) * sin_tol + 1.0;
    const double apart = std::hypot(a.cx - b.cx, a.cy - b.cy) - 0.5 * std::hypot(a.w, a.h) - 0.5 * std::hypot(b.w, b.h);
    if (apart > reach) return std::nullopt;
  }
  const auto ea = edges_of(a);
  const auto eb = edges_of(b);
  std::optional<WallPair> best;
  for (int i = 0; i < 4; ++i) {
    const Edge& p = ea[static_cast<std::size_t>(i)];
    if (!(p.length > 0.0)) continue;
    const Point2 p0 = p.p0;
    const double la = p.length, dx = p.dx, dy = p.dy;
    for (int j = 0; j < 4; ++j) {
      const Edge& q = eb[static_cast<std::size_t>(j)];
      if (!(q.length > 0.0)) continue;
      const Point2 q0 = q.p0, q1 = q.p1;
      if (std::abs(dx * q.dy - dy * q.dx) > sin_tol) continue;
      const double mx = 0.5 * (q0.x + q1.x) - p0.x, my = 0.5 * (q0.y + q1.y) - p0.y;
      if (std::abs(dx * my - dy * mx) > max_gap) continue;
      const double t0 = dx * (q0.x - p0.x) + dy * (q0.y - p0.y);
      const double t1 = dx * (q1.x - p0.x) + dy * (q1.y - p0.y);
      const double ov = std::min(la, std::max(t0, t1)) - std::max(0.0, std::min(t0, t1));
      if (!(ov > dilate_cells)) continue;
      if (!best || ov > best->overlap) best = WallPair{i, j, ov, la, q.length};
    }
  }
  return best;
}

bool cut_across_corridor(const OrientedRect& a, const OrientedRect& b, double max_cut, double min_ratio) {
  const auto w = connecting_walls(a, b, 2.0);
  if (!w || w->overlap > max_cut) return false;
  return depth_from_edge(a, w->wall_a) + depth_from_edge(b, w->wall_b) >= min_ratio * w->overlap;
}

}  // namespace ksmc::stdlib::indoor::blocks
