#include "stdlib/indoor/io/specks.h"

#include <vector>

#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::indoor::io {

std::size_t clear_specks(ClassGrid& grid, int max_cells) {
  if (max_cells < 1 || grid.empty()) return 0;
  constexpr auto kOccupied = static_cast<std::uint8_t>(Cell::Occupied), kFree = static_cast<std::uint8_t>(Cell::Free);
  cv::Mat1b occupied(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) occupied(r, c) = grid(r, c) == kOccupied ? 255 : 0;
  cv::Mat1i labels, stats;
  cv::Mat1d centroids;
  const int n = cv::connectedComponentsWithStats(occupied, labels, stats, centroids, 8, CV_32S);
  // A region is a speck when it is small and no cell beside it is anything but free.
  std::vector<char> small(static_cast<std::size_t>(n), 0);
  for (int l = 1; l < n; ++l)
    small[static_cast<std::size_t>(l)] = stats(l, cv::CC_STAT_WIDTH) <= max_cells && stats(l, cv::CC_STAT_HEIGHT) <= max_cells;
  std::vector<char> speck = small;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const int l = labels(r, c);
      if (l == 0 || !speck[static_cast<std::size_t>(l)]) continue;
      for (int dr = -1; dr <= 1 && speck[static_cast<std::size_t>(l)]; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = r + dr, cc = c + dc;
          if (rr < 0 || cc < 0 || rr >= grid.rows || cc >= grid.cols || (grid(rr, cc) != kFree && labels(rr, cc) != l)) {
            speck[static_cast<std::size_t>(l)] = 0;
            break;
          }
        }
    }
  // A small region within 2 * max_cells of a larger one is a fragment of it (the dots left of a
  // thin wall drawn broken, lab_d_scan), not a speck in open floor.
  cv::Mat1b not_large(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const int l = labels(r, c);
      not_large(r, c) = l == 0 || small[static_cast<std::size_t>(l)] != 0 ? 255 : 0;
    }
  cv::Mat1f to_large;
  cv::distanceTransform(not_large, to_large, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const float near = 2.0F * static_cast<float>(max_cells);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (labels(r, c) != 0 && to_large(r, c) <= near) speck[static_cast<std::size_t>(labels(r, c))] = 0;
  std::size_t changed = 0;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (speck[static_cast<std::size_t>(labels(r, c))] != 0 && labels(r, c) != 0) {
        grid(r, c) = kFree;
        ++changed;
      }
  return changed;
}

}  // namespace ksmc::stdlib::indoor::io
