// All boxes of one cluster: tilted boxes are taken out first (tilted_box.h), each time the
// rest is split into its connected parts again; a part without a tilted face is an upright
// box or a stack of them (stack_split.h).
#pragma once

#include <vector>

#include "stdlib/tabletop/perception/clusters.h"
#include "stdlib/tabletop/perception/stack_split.h"
#include "stdlib/tabletop/perception/tilted_box.h"

namespace ksmc::stdlib::tabletop::perception {

struct ClusterBoxOptions {
  BoxFitOptions box;
  bool split_stacks = true;
  StackOptions stacks;
  bool tilted = true;     // look for tilted boxes (off: upright boxes only, as before)
  TiltOptions tilt;
  ClusterOptions parts;   // re-clustering of the rest after a tilted box (tolerance, min points;
                          // scene_from_points sets CloudOptions::clusters)
  int max_tilted = 4;     // per cluster
};

// Boxes of `points` (table frame), at least one when `points` is not empty. `rays`: the
// whole cloud and the sensor, for the stacks' ray tests (stack_split.h) and for splitting the
// rest after a tilted box along grazing tops' rows as the cloud was
// (ClusterOptions::slant_factor); may be null (the tolerance alone).
std::vector<UprightBox> fit_cluster_boxes(const Points& points, const ClusterBoxOptions& options = {},
                                          const RayIndex* rays = nullptr);

}  // namespace ksmc::stdlib::tabletop::perception
