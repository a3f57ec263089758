// Objects above the table: the points between min_height and max_height over the table
// (inside its extent), grouped by PCL Euclidean clustering. Table-frame points in and out.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::stdlib::tabletop::perception {

struct ClusterOptions {
  double min_height = 0.012;   // m above the table top (below: table noise)
  double max_height = 0.6;     // m
  double table_margin = 0.02;  // m beyond the table's extent still counted as on the table
  double tolerance = 0.008;    // m, Euclidean neighbour distance (HOPE: 5 mm gaps, 4-pixel stride)
  std::size_t min_points = 40;
  std::size_t max_points = 10'000'000;
};

// Clusters of `table_points` (table frame) above a table of size `extent` centred on the
// origin, ordered by centroid x then y (deterministic ids).
std::vector<Points> cluster_objects(const Points& table_points, const Eigen::Vector2d& extent,
                                    const ClusterOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
