// overhang(o): evidence for an estimate that rests where no settled box could.
//
// A box resting on a face is in equilibrium only when its centre of mass lies over the region
// it stands on. A box that rests on other boxes (not on the table) therefore has its centre
// over the upward faces of its supporters, up to pose noise; one whose centre lies beyond
// them would topple. An estimate placed there is held by something hidden under its free part,
// or it is a false estimate (an extra or moved estimate set into a stack, a shifted or flipped
// box whose footprint lands off its supporter). A box on the table never overhangs: the table
// top is unbounded for this test.
#pragma once

#include <span>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

// Horizontal distance [m] from the centre of `box` to the convex hull of the upward faces of
// `supporters` (each face projected on the table plane; the upward face is the one whose
// normal is closest to the table normal); 0 when the centre lies over the hull, and 0 when
// there are no supporters.
double support_overhang(const Obb& box, std::span<const Obb> supporters);

// The centre of `box` lies beyond its supporters' upward faces by more than `margin` [m].
bool extract_overhang(const Obb& box, std::span<const Obb> supporters, double margin);

}  // namespace ksmc::stdlib::tabletop
