// Visible share of each box in a simulated depth view (scorer of ksmc-perception-sim): the
// pixels of the image where the box is the nearest hit among all boxes, divided by the pixels
// whose ray hits it when it is alone, counted on the image plane extended by one image width
// and height past each border (so a box the image border cuts is partly unseen). Boxes are on
// the table, so the table hides none of them. 1 for a box in full view, 0 for a box entirely
// behind others or out of the image.
#pragma once

#include <span>
#include <vector>

#include "tools/tabletop_sim/depth_render.h"

namespace ksmc::tools::perception {

std::vector<double> visible_fractions(const tools::tabletop_sim::Camera& camera,
                                      const tools::tabletop_sim::Pose& table_from_camera,
                                      std::span<const tools::tabletop_sim::Box> boxes, int stride);

}  // namespace ksmc::tools::perception
