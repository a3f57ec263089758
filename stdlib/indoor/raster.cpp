#include "stdlib/indoor/raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ksmc::stdlib::indoor {

SpanRaster::SpanRaster(const OrientedRect& r, int cols) : cols_(cols) {
  // Degenerate or non-finite rectangles cover no cell.
  if (!(r.w > 0.0) || !(r.h > 0.0) || !std::isfinite(r.w) || !std::isfinite(r.h) || !std::isfinite(r.cx) ||
      !std::isfinite(r.cy) || !std::isfinite(r.theta))
    return;
  empty_ = false;
  c_ = std::cos(r.theta);
  s_ = std::sin(r.theta);
  cx_ = r.cx;
  cy_ = r.cy;
  hw_ = 0.5 * r.w;
  hh_ = 0.5 * r.h;
  const double ey = std::abs(s_) * hw_ + std::abs(c_) * hh_;  // half extent along y
  const double lim = 1e9;  // keeps absurd coordinates representable
  row_begin_ = static_cast<int>(std::clamp(std::floor(cy_ - ey) - 1.0, -lim, lim));
  row_end_ = static_cast<int>(std::clamp(std::ceil(cy_ + ey) + 2.0, -lim, lim));
}

namespace {
// Interval of x where |a*x + b| <= h; returns false when empty. When the constraint does not
// depend on x it is taken half-open (-h <= b < h), so rectangles abutting along an
// axis-parallel edge never share a cell.
bool slab(double a, double b, double h, double& lo, double& hi) {
  if (std::abs(a) < 1e-15) {
    if (b >= -h && b < h) {
      lo = -std::numeric_limits<double>::infinity();
      hi = std::numeric_limits<double>::infinity();
      return true;
    }
    return false;
  }
  double x0 = (-h - b) / a, x1 = (h - b) / a;
  if (x0 > x1) std::swap(x0, x1);
  lo = x0;
  hi = x1;
  return true;
}
}  // namespace

RowSpan SpanRaster::span(int row) const {
  if (empty_ || row < row_begin_ || row >= row_end_) return {};
  const double yc = row - cy_;
  // Local coordinates of (x, row): u = c*(x-cx) + s*yc, v = -s*(x-cx) + c*yc.
  double ulo, uhi, vlo, vhi;
  if (!slab(c_, s_ * yc, hw_, ulo, uhi)) return {};
  if (!slab(-s_, c_ * yc, hh_, vlo, vhi)) return {};
  const double lo = std::max(ulo, vlo) + cx_;
  const double hi = std::min(uhi, vhi) + cx_;
  if (lo > hi) return {};
  // Cells whose centre x lies in [lo, hi) (half-open: abutting rectangles share no cell).
  const double first = std::ceil(std::max(lo, -1.0));
  const double end = std::ceil(std::min(hi, static_cast<double>(cols_) + 1.0));
  RowSpan sp{static_cast<int>(first), static_cast<int>(end)};
  sp.x0 = std::max(sp.x0, 0);
  sp.x1 = std::min(sp.x1, cols_);
  if (sp.x0 >= sp.x1) return {};
  return sp;
}

UnitRaster::UnitRaster(const OrientedRect& r, double wall_thickness, int cols)
    : outer(r, cols) {
  OrientedRect in = r;
  in.w -= 2.0 * wall_thickness;
  in.h -= 2.0 * wall_thickness;
  if (in.w > 0.0 && in.h > 0.0) inner = SpanRaster(in, cols);
}

OrientedRect door_rect(Point2 a, Point2 b, double thickness) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return OrientedRect{0.5 * (a.x + b.x), 0.5 * (a.y + b.y), std::hypot(dx, dy), thickness,
                      std::atan2(dy, dx)};
}

}  // namespace ksmc::stdlib::indoor
