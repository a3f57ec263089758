#include "stdlib/indoor/geometry.h"

#include <algorithm>
#include <cmath>

namespace ksmc::stdlib::indoor {

Frame::Frame(double theta) : theta_(theta), c_(std::cos(theta)), s_(std::sin(theta)) {}

double angle_off_quarter(double a) {
  const double q = 0.5 * kPi;
  double m = std::fmod(a, q);
  if (m < 0) m += q;
  return std::min(m, q - m);
}

std::optional<Box> box_in_frame(const OrientedRect& r, const Frame& frame, double angle_eps) {
  const double d = r.theta - frame.theta();
  if (angle_off_quarter(d) > angle_eps) return std::nullopt;
  // Whether the rectangle's w-axis lies along the frame's x-axis or its y-axis.
  const double q = 0.5 * kPi;
  const long k = std::lround(d / q);
  const bool swapped = (k % 2) != 0;
  const Point2 c = frame.to_local({r.cx, r.cy});
  const double hx = 0.5 * (swapped ? r.h : r.w);
  const double hy = 0.5 * (swapped ? r.w : r.h);
  return Box{c.x - hx, c.x + hx, c.y - hy, c.y + hy};
}

OrientedRect rect_from_box(const Box& b, const Frame& frame) {
  const Point2 c = frame.to_global({0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)});
  return OrientedRect{c.x, c.y, b.width(), b.height(), frame.theta()};
}

Box own_box(const OrientedRect& r) {
  const Point2 c = Frame(r.theta).to_local({r.cx, r.cy});
  return Box{c.x - 0.5 * r.w, c.x + 0.5 * r.w, c.y - 0.5 * r.h, c.y + 0.5 * r.h};
}

double distance_to_boundary(const Box& b, Point2 p) {
  const double dx = std::max({b.x0 - p.x, 0.0, p.x - b.x1}), dy = std::max({b.y0 - p.y, 0.0, p.y - b.y1});
  if (dx > 0.0 || dy > 0.0) return std::hypot(dx, dy);
  return std::min({p.x - b.x0, b.x1 - p.x, p.y - b.y0, b.y1 - p.y});
}

Box shift_box_wall(const Box& b, int wall, double delta) {
  Box o = b;
  switch (wall) {
    case 0: o.y0 -= delta; break;
    case 1: o.x1 += delta; break;
    case 2: o.y1 += delta; break;
    default: o.x0 -= delta; break;
  }
  return o;
}

double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool same_rect(const OrientedRect& a, const OrientedRect& b, double tol) {
  const auto ca = a.corners();
  const auto cb = b.corners();
  for (const auto& p : ca) {
    bool found = false;
    for (const auto& q : cb) {
      if (distance(p, q) <= tol) { found = true; break; }
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace ksmc::stdlib::indoor
