#include "stdlib/tabletop/extract_contact.h"

#include <cmath>

#include "stdlib/tabletop/extract_intersect.h"

namespace ksmc::stdlib::tabletop {

bool is_near_vertical(const Eigen::Vector3d& direction, const EvidenceParams& params) {
  return std::abs(direction.z()) >= std::cos(params.vertical_cone_rad);
}

bool contact_from_geometry(const PairGeometry& g, const EvidenceParams& params) {
  if (intersect_from_geometry(g, params)) return false;
  if (g.overlapping) return true;  // shallow overlap within tolerance: touching
  const double eps = g.stacked && is_near_vertical(g.direction, params) ? params.vertical_contact_eps
                                                           : params.contact_eps;
  return g.distance <= eps;
}

bool extract_contact(const Obb& a, const Obb& b, const EvidenceParams& params) {
  return contact_from_geometry(pair_geometry(a, b, params.max_contact_eps()), params);
}

}  // namespace ksmc::stdlib::tabletop
