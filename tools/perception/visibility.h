// What a simulated depth view shows of each box (scorer of ksmc-perception-sim).
//   * Visible share: the pixels of the image where the box is the nearest hit among all boxes,
//     divided by the pixels whose ray hits it when it is alone, counted on the image plane
//     extended by one image width and height past each border (so a box the image border cuts
//     is partly unseen). Boxes are on the table, so the table hides none of them. 1 for a box
//     in full view, 0 for a box entirely behind others or out of the image.
//   * Extents shown: whether one connected piece of the box's seen surface (the pixels inside
//     the image where it is the nearest hit, 4-neighbours on the grid) spans each of its three
//     extents, along its own axes, to within `tolerance` (by default the 1 cm; the
//     pixel grid alone leaves a few mm at each end). Two ends seen either side of an occluder
//     are two pieces: nothing in the cloud ties them to one box by itself. A box
//     standing on the table (an axis within 2 degrees of vertical, its bottom within
//     `tolerance` of the table) has its height shown when its top is seen: the table gives
//     its bottom. A box whose extents are not all shown cannot be recovered to that tolerance
//     from the cloud alone, however good the front end: its far end, or its foot on a box it
//     hides, is behind something.
#pragma once

#include <span>
#include <vector>

#include "tools/tabletop_sim/depth_render.h"

namespace ksmc::tools::perception {

struct BoxView {
  double visible = 0.0;        // visible share, [0, 1]
  bool extents_shown = false;  // all three extents spanned by its seen surface
};

std::vector<BoxView> box_views(const tools::tabletop_sim::Camera& camera,
                               const tools::tabletop_sim::Pose& table_from_camera,
                               std::span<const tools::tabletop_sim::Box> boxes, int stride, double tolerance = 0.01);

}  // namespace ksmc::tools::perception
