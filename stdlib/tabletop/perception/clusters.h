// Objects above the table: the points between min_height and max_height over the table
// (inside its extent), grouped by Euclidean clustering. Table-frame points in and out.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/perception/point_grid.h"

namespace ksmc::stdlib::tabletop::perception {

struct ClusterOptions {
  double min_height = 0.012;   // m above the table top (below: table noise)
  double max_height = 0.6;     // m
  double table_margin = 0.02;  // m beyond the table's extent still counted as on the table
  double tolerance = 0.008;    // m, Euclidean neighbour distance (HOPE: 5 mm gaps, 4-pixel stride);
                               // the floor of the tolerance scene_from_points derives (spacing_factor)
  double spacing_factor = 2.0; // scene_from_points: tolerance = max(tolerance, this x the median
                               // nearest-neighbour spacing of the points above the table); 0: fixed
  std::size_t min_points = 40;
  std::size_t max_points = 10'000'000;
  // Grazing tops (scene_from_points, where the sensor is known): a flat top seen at a slant
  // is sampled in rows `slant_factor` x r x step / |ray_z| apart along the ray's horizontal
  // direction (r the range, step the sensor's angular step measured from the cloud). Two
  // points are joined when their offset along that direction is within that spacing (at
  // most `max_slant` x the tolerance) and the rest of the offset within the tolerance.
  // 0: isotropic (the tolerance alone).
  double slant_factor = 2.0;
  double max_slant = 3.0;
};

// The points above the table (between min_height and max_height, inside the extent plus
// table_margin) with a grid over them (point_grid.h), built once: the front end measures
// their spacing and clusters them on the same grid.
class AboveTable {
 public:
  AboveTable(const Points& table_points, const Eigen::Vector2d& extent, const ClusterOptions& options);
  [[nodiscard]] const Points& points() const noexcept;
  // object_point_spacing of these points.
  [[nodiscard]] double spacing(std::size_t max_queries = 4000) const;
  // cluster_objects of these points with `options`' tolerance and point counts (isotropic:
  // no sensor, so slant_factor is not used).
  [[nodiscard]] std::vector<Points> clusters(const ClusterOptions& options) const;
  // The same, joining points along the rows of a grazing top (ClusterOptions::slant_factor)
  // seen from `sensor` (table frame).
  [[nodiscard]] std::vector<Points> clusters(const ClusterOptions& options, const Eigen::Vector3d& sensor) const;

 private:
  // Median over at most `max_queries` points spread evenly of the distance to the nearest
  // neighbour times scale(point index); 0 when fewer than two points.
  [[nodiscard]] double median_nearest(std::size_t max_queries, const std::function<double(std::size_t)>& scale) const;

  struct Index;  // the points and a grid over them
  std::shared_ptr<const Index> index_;
};

// Median distance from a point above the table (as cluster_objects selects them) to its
// nearest neighbour: the cloud's sampling step on the objects (sensor resolution and
// range, or a voxel filter's size). Over at most `max_queries` points spread evenly; 0
// when fewer than two points are above the table.
double object_point_spacing(const Points& table_points, const Eigen::Vector2d& extent, const ClusterOptions& options = {},
                            std::size_t max_queries = 4000);

// Clusters of `table_points` (table frame) above a table of size `extent` centred on the
// origin, ordered by centroid x then y (deterministic ids).
std::vector<Points> cluster_objects(const Points& table_points, const Eigen::Vector2d& extent,
                                    const ClusterOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
