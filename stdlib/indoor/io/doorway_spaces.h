// A room segmentation's post-step (segmentation.png): free space that no unit explains and that
// the nearest-space fill reached only through a doorway is a space of its own. Defect it
// addresses (docs/indoor_knowledge_segmentation.md, "Spaces behind a doorway"): a corridor about 1 m wide
// that the chain left without a unit has no cell over 0.6 m from a wall, so no core seeds it;
// the fill then hands it, door by door, to the offices beside it, and each office segment
// holds a stretch of corridor.
//
// Rule: the filled cells (free cells the fill labelled, not explained by a unit or a seeded
// space) fall into 4-connected components of one label each. A component of at least
// kMinSpace whose contact with the explained cells of its label (its cells with such a
// 4-neighbour) is at most kDoorway long is detached: the label reached it through a door, not
// across an open room edge. Detached components that touch each other are one space (the fill
// boundaries between them are arbitrary) and get one new id, above every id in use.
#pragma once

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

// `explained`: non-zero where a unit or a seeded space labelled the cell before the fill.
void detach_spaces_behind_doorways(const ClassGrid& grid, double resolution, const cv::Mat1b& explained, cv::Mat1w& label);

}  // namespace ksmc::stdlib::indoor::io
