// higher(a, b): a lies above b in the table frame. Precisely:
//
//   higher(a, b)  ⇔  min_z(a) ≥ max_z(b) − min(higher_tol, ½ · (max_z(b) − min_z(b)))
//
// i.e. a's lowest point is at or above b's highest point, up to a tolerance for
// pose noise that never exceeds half of b's vertical extent. Consequences: a box
// resting on b (or on the table) is higher than b; two boxes standing side by side
// are never higher than one another whatever their heights (no false support);
// the relation is irreflexive and antisymmetric for boxes of positive extent
// (min_z(a) ≥ centre_z(b) and min_z(b) ≥ centre_z(a) cannot both hold).
#pragma once

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

bool extract_higher(const Obb& a, const Obb& b, const EvidenceParams& params);

}  // namespace ksmc::stdlib::tabletop
