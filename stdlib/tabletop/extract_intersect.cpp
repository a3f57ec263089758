#include "stdlib/tabletop/extract_intersect.h"

#include "stdlib/tabletop/extract_contact.h"

namespace ksmc::stdlib::tabletop {

bool intersect_from_geometry(const PairGeometry& g, const EvidenceParams& params) {
  if (!g.overlapping) return false;
  if (g.contained) return true;
  // The vertical tolerance absorbs height noise between stacked bodies only.
  const double eps = g.stacked && is_near_vertical(g.direction, params) ? params.vertical_intersect_eps
                                                           : params.intersect_eps;
  return g.depth > eps;
}

bool extract_intersect(const Obb& a, const Obb& b, const EvidenceParams& params) {
  return intersect_from_geometry(pair_geometry(a, b, params.max_contact_eps()), params);
}

}  // namespace ksmc::stdlib::tabletop
