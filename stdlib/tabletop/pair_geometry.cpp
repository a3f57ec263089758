#include "stdlib/tabletop/pair_geometry.h"

#include "stdlib/tabletop/obb_distance.h"
#include "stdlib/tabletop/obb_sat.h"

namespace ksmc::stdlib::tabletop {

namespace {

bool all_vertices_inside(const Obb& inner, const Obb& outer) {
  for (int k = 0; k < 8; ++k)
    if (!outer.contains(inner.vertex(k), 1e-12)) return false;
  return true;
}

}  // namespace

PairGeometry pair_geometry(const Obb& a, const Obb& b, double exact_below) {
  PairGeometry g;
  const double a_lo = a.min_z(), a_hi = a.max_z(), b_lo = b.min_z(), b_hi = b.max_z();
  g.stacked = (a_lo > b_lo && a_hi > b_hi) || (b_lo > a_lo && b_hi > a_hi);
  const SatResult sat = obb_sat(a, b);
  if (sat.overlapping) {
    g.overlapping = true;
    g.distance = 0.0;
    g.depth = sat.depth;
    g.direction = sat.axis;
    g.contained = all_vertices_inside(a, b) || all_vertices_inside(b, a);
    return g;
  }
  if (sat.gap > exact_below) {
    g.distance = sat.gap;
    g.distance_exact = false;
    g.direction = sat.axis;
    return g;
  }
  const ClosestPoints cp = obb_closest_points(a, b);
  g.distance = cp.distance;
  const Eigen::Vector3d d = cp.on_b - cp.on_a;
  g.direction = d.norm() > 0.0 ? Eigen::Vector3d(d / d.norm()) : sat.axis;
  return g;
}

}  // namespace ksmc::stdlib::tabletop
