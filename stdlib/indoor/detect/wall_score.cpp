#include "stdlib/indoor/detect/wall_score.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::indoor::detect {
namespace {

// Calls f(x, y, nx, ny) for every sample of segment a-b (nx, ny: unit normal); returns count.
template <class F>
int for_samples(Point2 a, Point2 b, F&& f) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len = std::hypot(dx, dy);
  const int n = std::max(1, int(std::ceil(len - 1e-9))) + 1;
  const double nx = len > 0 ? -dy / len : 0.0, ny = len > 0 ? dx / len : 1.0;
  for (int i = 0; i < n; ++i) {
    const double t = double(i) / double(n - 1);
    f(a.x + t * dx, a.y + t * dy, nx, ny);
  }
  return n;
}

inline int cell_at(const ClassGrid& g, double x, double y) {
  const int c = int(std::lround(x)), r = int(std::lround(y));
  if (c < 0 || r < 0 || c >= g.cols || r >= g.rows) return -1;
  return g(r, c);
}

}  // namespace

double wall_weight(const ClassGrid& grid, Point2 a, Point2 b, const WallScoreParams& params) {
  const int tol = std::max(0, params.tolerance);
  int hits = 0;
  const int n = for_samples(a, b, [&](double x, double y, double nx, double ny) {
    for (int k = -tol; k <= tol; ++k)
      if (cell_at(grid, x + k * nx, y + k * ny) == int(Cell::Occupied)) {
        ++hits;
        return;
      }
  });
  return double(hits) / double(n);
}

double unit_weight(const ClassGrid& grid, const OrientedRect& rect, const WallScoreParams& params) {
  const auto c = rect.corners();
  double w = 1.0;
  for (int i = 0; i < 4; ++i) w = std::min(w, wall_weight(grid, c[i], c[(i + 1) % 4], params));
  return w;
}

double door_weight(const ClassGrid& grid, Point2 a, Point2 b, const DoorScoreParams& params) {
  const int hw = std::max(0, params.half_width);
  int hits = 0;
  const int n = for_samples(a, b, [&](double x, double y, double nx, double ny) {
    if (cell_at(grid, x, y) != int(Cell::Free)) return;
    for (int k = -hw; k <= hw; ++k) {
      const int v = cell_at(grid, x + k * nx, y + k * ny);
      if (v < 0 || v == int(Cell::Occupied)) return;
    }
    ++hits;
  });
  return double(hits) / double(n);
}

}  // namespace ksmc::stdlib::indoor::detect
