// contact(a, b): the boxes touch without intersecting — the EXACT distance between
// the solids (closest points, obb_distance.h) is at most the contact tolerance, or
// they overlap by no more than the intersect tolerance. Mutually exclusive with
// intersect(a, b) by construction. The larger vertical contact tolerance applies
// only to near-vertical gaps between stacked boxes (PairGeometry::stacked).
#pragma once

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pair_geometry.h"

namespace ksmc::stdlib::tabletop {

// True when the unit direction is within params.vertical_cone_rad of the table normal.
bool is_near_vertical(const Eigen::Vector3d& direction, const EvidenceParams& params);

bool contact_from_geometry(const PairGeometry& g, const EvidenceParams& params);
bool extract_contact(const Obb& a, const Obb& b, const EvidenceParams& params);

}  // namespace ksmc::stdlib::tabletop
