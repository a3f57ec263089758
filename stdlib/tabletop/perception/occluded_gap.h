// One box seen as two: a long box with something lying across it (a toothpaste under a
// crossing one, a book under a box) shows two ends, each its own cluster, and the part in
// between is hidden by what lies on it. Two upright boxes are the two ends of one when they
// are turned alike (`max_turn_deg`), lie on one line along a side (`tolerance` across it),
// share their cross-section, bottom and height (`tolerance`), are `min_gap` to `max_gap`
// apart, and the rays toward the space between them (their cross-section, inset by `inset`)
// are hidden: at least `min_rays` end before it, at least `hidden_share` of all the rays that
// meet it (ray_meeting.h, rays_meeting). Seen empty or holding a surface, the gap is real:
// two boxes in a row.
#pragma once

#include <cstddef>
#include <optional>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct OccludedGapOptions {
  bool enabled = true;
  double max_turn_deg = 3.0;
  double tolerance = 0.006;     // m
  double min_gap = 0.01;        // m
  double max_gap = 0.15;        // m
  double inset = 0.005;         // m
  double margin = 0.01;         // m, a ray ending this close to the gap ends in it
  std::size_t min_rays = 20;
  double hidden_share = 0.9;
};

// The box spanning `a` and `b` (upright boxes, table frame) when they are the two ends of one
// box whose middle is hidden, else nothing.
std::optional<UprightBox> bridge_occluded_gap(const UprightBox& a, const UprightBox& b, const RayIndex& rays,
                                              const OccludedGapOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
