// The tilt noise of a scene's pose estimates, read off the estimates themselves: most objects
// rest on a face (on the table or on the level top of a box), so the angle between a resting
// object's most vertical axis and the table normal is pose noise. With two independent tilt
// components of standard deviation sigma the tilt is Rayleigh-distributed, its median
// sigma * sqrt(2 ln 2); sigma is read from the median tilt of the objects within the stable
// tolerance. Leaning boxes lie beyond that tolerance and are left out; false estimates tilted
// within it are outliers the median ignores.
//
// The extractor obb.tilted (blocks.h) compares a box's tilt with it: a box tilted beyond the
// noise does not rest on a level face.
#pragma once

#include <cstddef>

#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct TiltNoise {
  double sigma = 0.0;     // [rad] per-component standard deviation of the resting tilts
  std::size_t tilts = 0;  // objects within the stable tolerance
};

// `stable_tol` [rad]: objects tilted more do not rest on a face and are not counted.
TiltNoise tilt_noise(const Scene& scene, double stable_tol);

}  // namespace ksmc::stdlib::tabletop
