// stable(o): some OBB edge is parallel to the table normal (z) within a tolerance angle.
#pragma once

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// Angle [rad] between the table normal and the box axis closest to it.
double tilt_angle(const Obb& box);

bool extract_stable(const Obb& box, const EvidenceParams& params);

}  // namespace ksmc::stdlib::tabletop
