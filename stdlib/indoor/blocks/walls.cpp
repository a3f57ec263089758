#include "stdlib/indoor/blocks/walls.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::indoor::blocks {

GeomClass classify_unit(const OrientedRect& r, double resolution, double big_size_m, double big_ratio) {
  const double lo = std::min(std::abs(r.w), std::abs(r.h)) * resolution;
  const double hi = std::max(std::abs(r.w), std::abs(r.h)) * resolution;
  if (hi > big_size_m) return GeomClass::HallLike;
  if (lo <= 0.0 || hi / lo > big_ratio) return GeomClass::CorridorLike;
  return GeomClass::RoomLike;
}

std::optional<WallPair> connecting_walls(const OrientedRect& a, const OrientedRect& b, double dilate_cells) {
  const auto ca = a.corners();
  const auto cb = b.corners();
  const double max_gap = 2.0 * dilate_cells + 1.0;
  const double sin_tol = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  std::optional<WallPair> best;
  for (int i = 0; i < 4; ++i) {
    const Point2 p0 = ca[static_cast<std::size_t>(i)], p1 = ca[static_cast<std::size_t>((i + 1) % 4)];
    const double la = std::hypot(p1.x - p0.x, p1.y - p0.y);
    if (!(la > 0.0)) continue;
    const double dx = (p1.x - p0.x) / la, dy = (p1.y - p0.y) / la;
    for (int j = 0; j < 4; ++j) {
      const Point2 q0 = cb[static_cast<std::size_t>(j)], q1 = cb[static_cast<std::size_t>((j + 1) % 4)];
      const double lb = std::hypot(q1.x - q0.x, q1.y - q0.y);
      if (!(lb > 0.0)) continue;
      const double ex = (q1.x - q0.x) / lb, ey = (q1.y - q0.y) / lb;
      if (std::abs(dx * ey - dy * ex) > sin_tol) continue;
      const double mx = 0.5 * (q0.x + q1.x) - p0.x, my = 0.5 * (q0.y + q1.y) - p0.y;
      if (std::abs(dx * my - dy * mx) > max_gap) continue;
      const double t0 = dx * (q0.x - p0.x) + dy * (q0.y - p0.y);
      const double t1 = dx * (q1.x - p0.x) + dy * (q1.y - p0.y);
      const double ov = std::min(la, std::max(t0, t1)) - std::max(0.0, std::min(t0, t1));
      if (!(ov > dilate_cells)) continue;
      if (!best || ov > best->overlap) best = WallPair{i, j, ov, la, lb};
    }
  }
  return best;
}

}  // namespace ksmc::stdlib::indoor::blocks
