// A box resting on another with its centre beyond the lower box's footprint. The box on top
// hides the lower box's top, and seen from the front, a lower box under a larger one often
// shows only its front face: the front end fits it as a strip, and the box on it overhangs
// it, as nothing at rest does (the scene graph then calls it hidden or false, "overhang").
// The lower box reaches further where the sensor could not see: it grows along its
// horizontal axes, on the side of the upper box's centre, until that centre lies `margin`
// inside its footprint, when the space it grows into (the lower box's cross-section over
// the added length, at least `min_probe` long, over its height, inset by `inset`)
// is hidden: at least `min_rays` rays end before it and they are at least `hidden_share` of
// all the rays that meet it (ray_meeting.h, rays_meeting; the lower box's own points left
// out, as its front hides its back trivially: a ray ending on the box on it hides the space).
// A space seen empty or holding a surface stays out, and so does one another box holds. An
// upper box resting on two or more boxes (a book across two) grows none of them.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct HiddenReachOptions {
  bool enabled = true;
  double rest_gap = 0.015;     // m, the upper box's bottom this close to the lower box's top, and the footprints this close: it rests there
  double margin = 0.01;        // m, the upper box's centre this far inside the grown footprint
  double max_growth = 0.15;    // m per side
  double min_probe = 0.02;     // m, the shortest space probed (a few mm of growth still needs rays)
  double inset = 0.005;        // m
  double ray_margin = 0.01;    // m, a ray ending this close to the space ends in it
  std::size_t min_rays = 20;
  double hidden_share = 0.9;
};

// Grows the upright boxes of `boxes` (table frame) that an upright box rests on with its
// centre beyond their footprint, where the rays say their far part is hidden. Returns how
// many sides grew.
int grow_hidden_reach(std::vector<UprightBox>& boxes, const RayIndex& rays, const HiddenReachOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
