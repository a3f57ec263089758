// A tilted box (tilted_box.h) is fitted from the faces the sensor saw. Its faces the sensor
// did not see (the one against the box it leans on, its underside over the box it is propped
// on) are placed by the extents of the seen ones, and a thickness read off a face seen
// edge-on is often too large: the box then cuts into the upright box it leans on (sim clouds:
// 5-55 mm, where the truth touches), and the rules read two boxes in one space, one of them
// false. Solid boxes do not cut into each other, and the sensor says nothing against a
// thinner box where it saw nothing: each tilted box that overlaps an upright box deeper
// than `min_depth` is cut back on one of its unseen faces, the one needing the least cut,
// by the least depth that leaves the two at most `min_depth` apart in overlap. Its lowest
// corner is then lowered back to where it was (a leaning box's foot stays on what it stands
// on), unless the cut without lowering is less: a box lying across an upright one and fitted
// too thick on its unseen underside is cut there, and lowering it would press that side back
// into the upright box (sim clouds: a 27 mm cut where 8 mm of underside was too much). A face is unseen when at most `max_seen` of the box's points lie within `seen_margin`
// of it (over its outline), the points on or in other boxes left out. A box that would need
// more than `max_cut` of an extent is left as it was.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct LeanSeatOptions {
  bool enabled = true;
  double seen_margin = 0.004;  // m
  std::size_t max_seen = 10;
  double max_cut = 0.5;        // share of the extent cut
  double min_depth = 0.001;    // m
};

// Cuts back the tilted boxes of `boxes` (table frame) that overlap an upright box; `own[i]`
// are box i's points (only the tilted boxes' are read). Returns how many faces were cut.
int seat_leaning_boxes(std::vector<UprightBox>& boxes, const std::vector<Points>& own,
                       const LeanSeatOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
