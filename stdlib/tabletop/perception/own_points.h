// The points a box owns in its cluster, for the cloud likelihood and the passes that read a
// box's points. A cluster with one box gives it all its points (for the likelihood, with
// `not_below`, none under its bottom). A cluster with several (a stack split, a box cut
// where the sensor saw under it) gives each box the points within
// `margin` of it (noise), but not those of another box's layer: with a box of the cluster
// standing on it, none higher than its top, and with it standing on one, none lower than its
// bottom (each by `layer_margin`). The split put the boundary there; a bottle's shoulders
// above its body's box would otherwise pull that box up in the cloud likelihood. A box stands
// on another when its bottom is within `stand_gap` of the other's top and part of its
// footprint is over the other's.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct OwnPointsOptions {
  double margin = 0.01;        // m around the box
  double layer_margin = 0.0;   // m above its top / below its bottom (noise; the front end: 3 x its depth noise)
  double stand_gap = 0.01;     // m; a box stands on another when its bottom is this close to the other's top
  // A point nearer another box of the cluster by more than `layer_margin` is that box's (a box
  // leaning on this one, one beside it within the margin). The cloud likelihood's points use
  // it; the front end's passes that test a box's shape against its points (face strips, cuts
  // where the sensor saw under) read the points near it whoever owns them.
  bool nearest = false;
  // A point lower than the box's bottom by more than `layer_margin` is not its own, even when
  // the box is its cluster's only one: it is seen on something under the box that the front
  // end made no box of (the visible rim or side of a box it hides). Its own surface ends at its
  // bottom; in the cloud likelihood such points would tilt the box down towards them, and a
  // box hovering at a slant reads as a false estimate, not as one resting on a hidden object.
  // The cloud likelihood's points use it, like `nearest`.
  bool not_below = false;
};

// The points of `cluster` that boxes[i] owns; `cluster_of[j]` names box j's cluster,
// `cluster` is boxes[i]'s (table frame).
Points own_points(const std::vector<UprightBox>& boxes, const std::vector<std::size_t>& cluster_of, std::size_t i,
                  const Points& cluster, const OwnPointsOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
