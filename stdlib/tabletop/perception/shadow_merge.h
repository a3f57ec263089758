// Clusters split by an occlusion shadow: a box resting across a lower box hides a strip of
// the lower box's top behind it (seen from the sensor), and the top's far part becomes a
// cluster of its own. Two clusters are one when the far one's top and a flat part of the
// near one lie on one plane, and the strip between them is the shadow that the near
// cluster's higher points cast on that plane from the sensor. With the cloud's rays, the
// sensor must not have seen under the plane between the two tops (inside the convex hull of
// their points): a neighbour of about the same height, with the table seen between the two,
// is not the far part of the same top.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::stdlib::tabletop::perception {

struct ShadowMergeOptions {
  bool enabled = true;
  double plane_band = 0.004;   // m, points within this of the far top's height are on its plane
  double occluder_above = 0.01; // m, the near cluster's points this far above the plane cast the shadow
  double reach = 0.01;         // m, the shadow must come this close to both tops' points (2D)
  std::size_t min_points = 20; // on the plane (highest in their 5 mm cell) in each cluster, and above it in the near one
  double neighbourhood = 0.2;  // m, only clusters whose footprints' boxes are this close are compared
  // The rays' test: inside the convex hull of both tops' points, inset by `slab_inset`, at most
  // max(`max_seen_through`, `seen_through_share` x the tops' points) rays may cross the height
  // `slab_top` under the plane and end lower than both `slab_depth` under that and half of it.
  double slab_top = 0.006;       // m under the plane
  double slab_depth = 0.008;     // m
  double slab_inset = 0.02;      // m
  std::size_t max_seen_through = 5;
  double seen_through_share = 0.02;
};

// `clusters` (table frame) with the shadow-split ones joined: each group takes the place of
// its first cluster, its clusters' points in their order (deterministic). `sensor`: the
// cloud origin in the table frame; `rays`: the whole cloud seen from it (none: no rays' test).
std::vector<Points> merge_shadow_split(std::vector<Points> clusters, const Eigen::Vector3d& sensor,
                                       const ShadowMergeOptions& options = {}, const RayIndex* rays = nullptr);

}  // namespace ksmc::stdlib::tabletop::perception
