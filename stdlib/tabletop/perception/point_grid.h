// Neighbour queries on a uniform grid: the points of a cloud sorted by cell (cells of the
// grid's radius), the cells of one (x, y) column adjacent. A table of where each column
// starts (over the points' bounding box, when that is not too large) finds a column at once;
// otherwise a binary search does. Region growing, normals and the clustering of the points
// above the table read it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::stdlib::tabletop::perception {

// The index of the cell of size `size` holding coordinate `v` (cells [k size, (k + 1) size)).
inline long cell_of(double v, double size) { return std::lround(std::floor(v / size)); }

class PointGrid {
 public:
  // `points` must outlive the grid.
  PointGrid(const Points& points, double radius);
  // Indices of the points within the grid's radius of `p` (a fixed order for fixed input).
  void neighbours(const Eigen::Vector3d& p, std::vector<int>& out) const;
  // Indices of the points within `radius` of `p` (any radius; a fixed order for fixed input).
  void within(const Eigen::Vector3d& p, double radius, std::vector<int>& out) const;
  [[nodiscard]] double radius() const noexcept { return radius_; }

 private:
  const Points& points_;
  double radius_;
  std::vector<std::pair<std::uint64_t, int>> cells_;  // (cell key, point index), sorted
  long x0_ = 0, y0_ = 0, nx_ = 0, ny_ = 0;            // the columns' bounding box (cells)
  std::vector<std::uint32_t> column_start_;           // nx_ * ny_ + 1 offsets into cells_, or empty
  [[nodiscard]] std::uint64_t key(long x, long y, long z) const;
};

// One point per occupied `voxel` cube (the first in input order): a sparser copy for quick
// tests, and the cloud likelihood's independent observations (`cloud.surface`'s voxel).
Points voxel_subsample(const Points& points, double voxel);

}  // namespace ksmc::stdlib::tabletop::perception
