#include "stdlib/tabletop/extract_overhang.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ksmc::stdlib::tabletop {

namespace {

using Point = Eigen::Vector2d;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Convex hull, counter-clockwise, without collinear points (Andrew's monotone chain).
std::vector<Point> convex_hull(std::vector<Point> p) {
  std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (p.size() < 3) return p;
  std::vector<Point> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i > 0; --i) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0.0) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

double segment_distance(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The four corners of the box's upward face, projected on the table plane.
void add_upward_face(const Obb& box, std::vector<Point>& out) {
  int up = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(box.axes(2, i)) > std::abs(box.axes(2, up))) up = i;
  const double sign = box.axes(2, up) >= 0.0 ? 1.0 : -1.0;
  const int u = (up + 1) % 3, v = (up + 2) % 3;
  const Eigen::Vector3d face = box.center + sign * box.half(up) * box.axes.col(up);
  for (const double su : {-1.0, 1.0})
    for (const double sv : {-1.0, 1.0})
      out.push_back((face + su * box.half(u) * box.axes.col(u) + sv * box.half(v) * box.axes.col(v)).head<2>());
}

}  // namespace

double support_overhang(const Obb& box, std::span<const Obb> supporters) {
  if (supporters.empty()) return 0.0;
  std::vector<Point> corners;
  for (const Obb& s : supporters) add_upward_face(s, corners);
  const std::vector<Point> hull = convex_hull(std::move(corners));
  const Point c = box.center.head<2>();
  if (hull.size() < 3) {  // a degenerate face (a board seen edge-on): distance to the segment
    return hull.size() == 1 ? (c - hull[0]).norm() : segment_distance(c, hull[0], hull[1]);
  }
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    if (cross(a, b, c) < 0.0) inside = false;  // right of a counter-clockwise edge: outside
    nearest = std::min(nearest, segment_distance(c, a, b));
  }
  return inside ? 0.0 : nearest;
}

bool extract_overhang(const Obb& box, std::span<const Obb> supporters, double margin) {
  return support_overhang(box, supporters) > margin;
}

}  // namespace ksmc::stdlib::tabletop
