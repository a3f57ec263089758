// A box whose points start above the table (box_fit.h: the lowest 1 % of its points higher
// than BoxFitOptions::float_gap) is fitted from there up, as if it rested on something. When a nearer
// surface hides the space under it, the missing part is occlusion, not air: the box stands on
// the table behind what hides its foot (a carton behind a lower box is seen from its
// shoulder up). The space under the box (its footprint, inset, from the table up to its
// bottom) is read off the cloud's rays (sensor -> point, extended past the point):
//   * `before`: the ray ends more than `margin` before it enters the space (a nearer surface);
//   * `inside`: the ray ends in it (within `margin`): a surface there, e.g. the box it rests on;
//   * `through`: the ray passes through it and ends behind (the space was seen empty).
// The box grows down to the table when the rays toward that space are hidden: at least
// `min_rays` of them end before it and they are at least `hidden_share` of the three kinds;
// and when no other box lies under its footprint (within `rest_depth` below its bottom): a
// box resting on another is hidden underneath by the box it rests on. With another box
// under its footprint farther down, the space is the one between that box's top and its
// bottom, and the box grows down to that top when the space is hidden: a box lying on a
// taller one, seen from its top, its sides hidden by its neighbours.
// The box's own points (inside the fitted box, grown by `margin`) are not counted: a ray to
// its top continues through the box into the space under it.
// The other way round, a box lying on a box it overhangs can hide the lower box's top and
// upper sides: the lower box is fitted too short and the upper one floats over it. Then the
// lower box grows up to the upper one's bottom when the column over its footprint is hidden
// (rays ending on the upper box count as hiding it). So it does when the upper box is over
// the lower one by less than the fit's float gap, or within `rest_depth` of it, with a gap over
// `close_gap` (a book on a book under a larger one: its upper sides hidden, it was fitted
// 13-24 mm short, and the box on it hovered).
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/box_fit.h"
#include "stdlib/tabletop/perception/ray_meeting.h"

namespace ksmc::stdlib::tabletop::perception {

struct HiddenBottomOptions {
  bool enabled = true;
  double inset = 0.005;        // m, the space under the box shrunk by this on every side
  double margin = 0.01;        // m, a ray ending this close to the space ends in it
  std::size_t min_rays = 20;
  double hidden_share = 0.9;
  double rest_depth = 0.015;   // m
  // m; a box over another by less than the fit's float gap, or within rest_depth of it, with a
  // gap wider than this (and the column over the lower box hidden), closes it: the lower box
  // grows up to its bottom.
  double close_gap = 0.01;
};

// How the rays (RayIndex: the cloud and its sensor) meet the space under `box` (an upright
// box, table frame), from `floor` (a height) up to its bottom.
SpaceUnder rays_under(const UprightBox& box, const RayIndex& rays, const HiddenBottomOptions& options = {},
                      double floor = 0.0);

// Grows each upright box of `boxes` whose bottom is above `float_gap` (the box fit's), that
// rests on no other box of `boxes` and whose space under it is hidden, down to the surface
// under it (its top kept): the top of the highest other box under its footprint (one of its
// footprint's points over that box, or a point of that box's top under its footprint, inset),
// or the table. When that space is not hidden as a whole but the column over that highest box is
// (the floating box lies on it and overhangs it, so the sensor saw neither the lower box's
// top nor its upper sides), the lower box grows up to the floating box's bottom instead. So it
// does for a box over another by less than `float_gap`, or resting on it within `rest_depth`,
// with a gap wider than `close_gap`. Returns how many grew. Boxes not upright are left alone.
int grow_hidden_bottoms(std::vector<UprightBox>& boxes, const RayIndex& rays, double float_gap,
                        const HiddenBottomOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
