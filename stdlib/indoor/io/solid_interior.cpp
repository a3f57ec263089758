#include "stdlib/indoor/io/solid_interior.h"

#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::indoor::io {

std::size_t unexplain_solid_interior(ClassGrid& grid, double depth_cells) {
  if (!(depth_cells > 0.0) || grid.empty()) return 0;
  // Distance of every non-free cell to the nearest free cell (free cells are the zeros).
  cv::Mat1b not_free(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) not_free(r, c) = grid(r, c) == static_cast<std::uint8_t>(Cell::Free) ? 0 : 255;
  cv::Mat1f dist;
  cv::distanceTransform(not_free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  std::size_t changed = 0;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (grid(r, c) == static_cast<std::uint8_t>(Cell::Occupied) && dist(r, c) > depth_cells) {
        grid(r, c) = static_cast<std::uint8_t>(Cell::Unknown);
        ++changed;
      }
  return changed;
}

}  // namespace ksmc::stdlib::indoor::io
