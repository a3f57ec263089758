// higher(a, b): a lies above b in the table frame. Precisely, with the face heights
//
//   bottom(a) = z of the centre of a's lowest face  = centre_z(a) − max_k half_k · |axis_k · z|
//   top(b)    = z of the centre of b's highest face = centre_z(b) + max_k half_k · |axis_k · z|
//
// (the face whose normal is closest to the vertical; for a box lying flat these are its
// bottom and top faces)
//
//   higher(a, b)  ⇔  bottom(a) ≥ top(b) − min(higher_tol, top(b) − centre_z(b))
//
// i.e. a's lowest face is at or above b's highest face, up to a tolerance for pose noise
// that never exceeds b's half-height (so a is at least above b's centre). Face centres rather than the lowest /
// highest vertex: a box tilted by a few degrees within the `stable` tolerance drops a
// corner by half its width · sin(tilt) (15 mm for a 20 cm box at 4.5°), which would break
// the relation for a box resting on another one. Consequences: a box resting on b (or on
// the table) is higher than b; two boxes standing side by side are never higher than one
// another whatever their heights (no false support); the relation is irreflexive and
// antisymmetric for boxes of positive extent (bottom(a) ≥ centre_z(b) and bottom(b) ≥
// centre_z(a) cannot both hold, since bottom(x) < centre_z(x)).
#pragma once

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// Half the vertical extent measured at face centres: max_k half_k · |axis_k · z|.
double face_half_height(const Obb& box);

bool extract_higher(const Obb& a, const Obb& b, const EvidenceParams& params);

}  // namespace ksmc::stdlib::tabletop
