// How far each cell of a classified map lies from the nearest free cell: the field the
// `geom.hollow` extractor reads to find regions a unit covers but the sensor never saw into
// (a courtyard, a light well, a block of unexplored space).
#pragma once

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor {

// Euclidean distance in cells from each cell to the nearest Free cell (0 on free cells). A map
// with no free cell gives every cell the map's diagonal.
cv::Mat1f free_distance(const ClassGrid& map);

// The field at a point (cells, image convention), also outside the map: the distance of the
// nearest cell of the map plus the distance to the map's edge; infinite at a non-finite point.
double free_distance_at(const cv::Mat1f& field, double col, double row);

}  // namespace ksmc::stdlib::indoor
