// The vertical noise of a scene's pose estimates, read off the estimates themselves: every
// stable object rests on something (the table or the top face of a body under it), so the
// gap between its lowest point and the nearest supporting surface below it is, for a real
// resting object, pose noise. The robust scale of those gaps (1.4826 × median |gap|, the
// standard deviation of a zero-mean Gaussian) is the scene's vertical gap uncertainty.
// False estimates and hidden objects are outliers the median ignores.
//
// The near-vertical contact and intersect tolerances of the extractors are derived from it
// (blocks.h): a gap or penetration within `k` standard deviations is noise, not a relation
// (docs/tabletop_kit.md, "Tolerances from the pose uncertainty").
#pragma once

#include <cstddef>
#include <span>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct GapNoise {
  double sigma = 0.0;     // [m] robust standard deviation of the resting gaps
  std::size_t gaps = 0;   // stable objects with a surface under them within `reach`
};

// The signed gap [m] between the lowest point of boxes[i] and the nearest surface it can rest
// on: the table top (z = 0) or the top of another box that rests on a face (tilt within
// `stable_tol` [rad]), whose footprint overlaps boxes[i]'s and whose top lies below boxes[i]'s
// centre. Negative: the box cuts into that surface. boxes[i] itself may be tilted.
double rest_gap(std::span<const Obb> boxes, std::size_t i, double stable_tol);

// `stable_tol` [rad]: objects tilted more are not resting on a face; `reach` [m]: surfaces
// farther than this above or below an object's lowest point are not its support.
GapNoise gap_noise(const Scene& scene, double stable_tol, double reach = 0.03);

// The near-vertical tolerance derived from the gap noise: k·sigma within [lo, hi]; `hi` when
// fewer than `min_gaps` gaps were seen (too little to judge: the stdlib's fixed tolerance).
double vertical_tolerance(const GapNoise& noise, double k, double lo, double hi, std::size_t min_gaps = 3);

}  // namespace ksmc::stdlib::tabletop
