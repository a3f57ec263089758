// How the cloud's rays meet a space (a box, table frame): each line of sight (sensor -> point,
// going on past its point) that crosses the space either ends more than `margin` before it
// (something nearer hides the space), ends in it (a surface there), or passes through it and
// ends behind (the space was seen empty). The ray tests of the front end read spaces this way:
// under a floating box (hidden_bottom.h), beside a box's far end (hidden_reach.h), between two
// ends of one box (occluded_gap.h), under a leaning box's foot (tilted_foot.h), under a top
// peeled off a stack (stack_split.h).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/line_of_sight.h"

namespace ksmc::stdlib::tabletop::perception {

enum class RayMeets { before, inside, through };

// Calls f(ray, how) for every ray (RayIndex: the cloud and its sensor) whose line meets `space`,
// leaving out the rays to points within `margin` of one of the boxes `own` (a box's own surface)
// and those shorter than `margin`.
template <class F>
void for_each_meeting(const Obb& space, const std::vector<Obb>& own, const RayIndex& rays, double margin, F&& f) {
  const FreeSpace& seen = rays.free_space();
  const Eigen::Vector3d o = in_box_axes(space, seen.sensor - space.center);
  rays.for_each_toward(space, [&](std::size_t ray) {
    const Eigen::Vector3d& p = seen.points[ray];
    const Eigen::Vector3d seg = p - seen.sensor;
    const double len = seg.norm();
    if (len <= margin) return;
    for (const Obb& b : own)
      if ((in_box_axes(b, p - b.center).cwiseAbs() - b.half).maxCoeff() <= margin) return;
    double enter = 0.0, leave = std::numeric_limits<double>::infinity();  // the ray, past p too
    if (!slab_span(space, o, in_box_axes(space, seg), enter, leave)) return;
    const double slack = margin / len;
    f(ray, 1.0 < enter - slack ? RayMeets::before : 1.0 > leave + slack ? RayMeets::through : RayMeets::inside);
  });
}

struct SpaceUnder {
  std::size_t before = 0, inside = 0, through = 0;
};

// The counts of for_each_meeting's three kinds.
SpaceUnder rays_meeting(const Obb& space, const std::vector<Obb>& own, const RayIndex& rays, double margin);

}  // namespace ksmc::stdlib::tabletop::perception
