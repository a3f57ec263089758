// overlap(a, b) and flatter(a, b): evidence for two estimates of one object.
//
// A duplicated detection or a copy of a box shifted deep into it occupies mostly the same
// volume as the box it copies. Such a pair cuts each other like any intersecting pair, so
// r14 blames both alike and both stay undecided. Two solid boxes cannot share most of their
// volume: at most one of such a pair is a real object, and the one that rests the way a
// settled box rests (level on its supporter) is the better explanation of the two.
#pragma once

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// Share of the smaller box's volume that lies inside the other box, both boxes first
// shrunk by `shrink` [m] on every side (so that a penetration within the pose noise does not
// count): the cell centres of a regular grid over the smaller shrunk box, counted inside the
// other. 0 when either shrunk box is empty.
double shared_volume_fraction(const Obb& a, const Obb& b, double shrink);

// The boxes share at least `min_fraction` of the smaller one's volume (shared_volume_fraction).
bool extract_overlap(const Obb& a, const Obb& b, double shrink, double min_fraction);

// a rests flatter than b: a's tilt (the angle between the table normal and its closest box
// axis) is smaller than b's by more than `margin` [rad].
bool extract_flatter(const Obb& a, const Obb& b, double margin);

}  // namespace ksmc::stdlib::tabletop
