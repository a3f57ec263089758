#include "tools/tabletop_sim/relations.h"

#include <algorithm>
#include <cmath>

namespace ksmc::tools::tabletop_sim {

namespace {

using Polygon = std::vector<Eigen::Vector2d>;

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Counter-clockwise convex hull (Andrew's monotone chain).
Polygon convex_hull(Polygon pts) {
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (pts.size() < 3) return pts;
  Polygon hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Sutherland-Hodgman clip of a polygon against one half-plane  sign * p[axis] <= limit.
Polygon clip(const Polygon& poly, int axis, double sign, double limit) {
  Polygon out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % n];
    const double da = sign * a[axis] - limit;
    const double db = sign * b[axis] - limit;
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

double area(const Polygon& poly) {
  double s = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    s += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * std::abs(s);
}

double bounding_radius(const Box& b) { return 0.5 * b.size.norm(); }

}  // namespace

bool is_stable(const Box& b, double tolerance) { return tilt_from_vertical(b.pose.q) <= tolerance; }

SupportGeometry support_geometry(const Box& upper, const Box& lower) {
  const Eigen::Matrix3d r = lower.pose.rotation();
  const int k = vertical_axis(lower.pose.q);
  const double s = r(2, k) >= 0 ? 1.0 : -1.0;
  const Eigen::Vector3d n = s * r.col(k);
  const Eigen::Vector3d plane = lower.pose.t + n * 0.5 * lower.size[k];
  const int a = (k + 1) % 3;
  const int c = (k + 2) % 3;

  const auto verts = box_vertices(upper);
  SupportGeometry g;
  g.gap = 1e9;
  for (const auto& v : verts) g.gap = std::min(g.gap, n.dot(v - plane));
  // Upper's bottom face: the vertices within 2 mm of its lowest one, in lower's face coordinates.
  Polygon face;
  for (const auto& v : verts) {
    if (n.dot(v - plane) <= g.gap + 0.002) {
      const Eigen::Vector3d d = v - lower.pose.t;
      face.emplace_back(d.dot(r.col(a)), d.dot(r.col(c)));
    }
  }
  Polygon poly = convex_hull(face);
  if (poly.size() < 3) return g;
  const double ha = 0.5 * lower.size[a];
  const double hc = 0.5 * lower.size[c];
  poly = clip(poly, 0, 1.0, ha);
  poly = clip(poly, 0, -1.0, ha);
  poly = clip(poly, 1, 1.0, hc);
  poly = clip(poly, 1, -1.0, hc);
  g.area = poly.size() >= 3 ? area(poly) : 0.0;
  return g;
}

Relations compute_relations(std::span<const Box> boxes, const RelationParams& params) {
  Relations rel;
  const int n = static_cast<int>(boxes.size());
  rel.stable.resize(boxes.size());
  for (int i = 0; i < n; ++i) rel.stable[static_cast<std::size_t>(i)] = is_stable(boxes[static_cast<std::size_t>(i)], params.stable_tolerance);

  auto supports = [&](int upper, int lower) {
    const Box& u = boxes[static_cast<std::size_t>(upper)];
    const Box& l = boxes[static_cast<std::size_t>(lower)];
    if (!rel.stable[static_cast<std::size_t>(upper)] || !rel.stable[static_cast<std::size_t>(lower)]) return false;
    if (u.pose.t.z() <= l.pose.t.z()) return false;
    const SupportGeometry g = support_geometry(u, l);
    return std::abs(g.gap) <= params.support_gap && g.area >= params.min_support_area;
  };

  for (int i = 0; i < n; ++i) {
    const Box& bi = boxes[static_cast<std::size_t>(i)];
    const double low = lowest_z(bi);
    if (low <= params.contact_gap) {
      if (rel.stable[static_cast<std::size_t>(i)] && std::abs(low) <= params.support_gap) {
        rel.support.emplace_back(i, kTableIndex);
      } else {
        rel.contact.emplace_back(i, kTableIndex);
      }
    }
    for (int j = i + 1; j < n; ++j) {
      const Box& bj = boxes[static_cast<std::size_t>(j)];
      if ((bi.pose.t - bj.pose.t).norm() > bounding_radius(bi) + bounding_radius(bj) + params.contact_gap) continue;
      if (supports(i, j)) {
        rel.support.emplace_back(i, j);
      } else if (supports(j, i)) {
        rel.support.emplace_back(j, i);
      } else if (box_distance(bi, bj) <= params.contact_gap) {
        rel.contact.emplace_back(i, j);
      }
    }
  }
  std::sort(rel.support.begin(), rel.support.end());
  std::sort(rel.contact.begin(), rel.contact.end());
  return rel;
}

}  // namespace ksmc::tools::tabletop_sim
