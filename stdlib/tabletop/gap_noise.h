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

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct GapNoise {
  double sigma = 0.0;     // [m] robust standard deviation of the resting gaps
  std::size_t gaps = 0;   // stable objects with a surface under them within `reach`
};

// `stable_tol` [rad]: objects tilted more are not resting on a face; `reach` [m]: surfaces
// farther than this above or below an object's lowest point are not its support.
GapNoise gap_noise(const Scene& scene, double stable_tol, double reach = 0.03);

// The near-vertical tolerance derived from the gap noise: k·sigma within [lo, hi]; `hi` when
// fewer than `min_gaps` gaps were seen (too little to judge: the stdlib's fixed tolerance).
double vertical_tolerance(const GapNoise& noise, double k, double lo, double hi, std::size_t min_gaps = 3);

}  // namespace ksmc::stdlib::tabletop
