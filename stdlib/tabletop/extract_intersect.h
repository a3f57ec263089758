// intersect(a, b): the boxes penetrate deeper than the intersect tolerance (SAT
// penetration depth over 15 axes, obb_sat.h), or one box contains the other. The
// larger vertical tolerance applies only when the minimum-overlap axis is
// near-vertical AND the boxes are stacked (PairGeometry::stacked).
#pragma once

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pair_geometry.h"

namespace ksmc::stdlib::tabletop {

bool intersect_from_geometry(const PairGeometry& g, const EvidenceParams& params);
bool extract_intersect(const Obb& a, const Obb& b, const EvidenceParams& params);

}  // namespace ksmc::stdlib::tabletop
