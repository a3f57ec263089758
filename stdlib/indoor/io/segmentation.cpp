#include "stdlib/indoor/io/segmentation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <stdexcept>
#include <vector>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/world_images.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

cv::Mat1w render_segmentation(const ClassGrid& grid, const WorldResult& w) {
  validate_world(w, false);
  if (grid.empty()) throw std::invalid_argument("segmentation: empty map");
  const auto free_cell = [&grid](int r, int c) { return grid(r, c) == static_cast<std::uint8_t>(Cell::Free); };
  cv::Mat1i owner(grid.rows, grid.cols, -1);  // index into w.units
  cv::Mat1f depth(grid.rows, grid.cols, 0.0f);
  std::vector<Point2> centre(w.units.size());
  for (std::size_t i = 0; i < w.units.size(); ++i) {
    const auto& u = w.units[i];
    if (!finite_quad(u.corners)) continue;
    const auto& q = u.corners;
    centre[i] = {(q[0].x + q[1].x + q[2].x + q[3].x) / 4.0, (q[0].y + q[1].y + q[2].y + q[3].y) / 4.0};
    double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
    for (const auto& p : q) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const int c0 = std::max(0, static_cast<int>(std::ceil(x0))), c1 = std::min(grid.cols - 1, static_cast<int>(std::floor(x1)));
    const int r0 = std::max(0, static_cast<int>(std::ceil(y0))), r1 = std::min(grid.rows - 1, static_cast<int>(std::floor(y1)));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        if (!free_cell(r, c)) continue;
        const Point2 p{static_cast<double>(c), static_cast<double>(r)};
        const auto d = static_cast<float>(depth_inside(q, p));
        if (!(d > 0.0f)) continue;
        int& o = owner(r, c);
        float& best = depth(r, c);
        bool take = o < 0 || d > best;
        if (!take && d == best) {  // tie: the nearer centre, then the smaller id
          const auto j = static_cast<std::size_t>(o);
          const double di = std::hypot(p.x - centre[i].x, p.y - centre[i].y);
          const double dj = std::hypot(p.x - centre[j].x, p.y - centre[j].y);
          take = di < dj || (di == dj && u.id < w.units[j].id);
        }
        if (take) {
          o = static_cast<int>(i);
          best = d;
        }
      }
    }
  }
  cv::Mat1w label(grid.rows, grid.cols, static_cast<std::uint16_t>(0));
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (const int o = owner(r, c); o >= 0) label(r, c) = static_cast<std::uint16_t>(w.units[static_cast<std::size_t>(o)].id);
  // Multi-source BFS over 4-connected free cells from every labelled cell, row-major order.
  std::deque<std::pair<int, int>> queue;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (label(r, c) != 0) queue.emplace_back(r, c);
  constexpr int kDr[4] = {-1, 0, 0, 1}, kDc[4] = {0, -1, 1, 0};
  while (!queue.empty()) {
    const auto [r, c] = queue.front();
    queue.pop_front();
    for (int k = 0; k < 4; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (nr < 0 || nc < 0 || nr >= grid.rows || nc >= grid.cols) continue;
      if (label(nr, nc) != 0 || !free_cell(nr, nc)) continue;
      label(nr, nc) = label(r, c);
      queue.emplace_back(nr, nc);
    }
  }
  return label;
}

void write_segmentation_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w) {
  runtime::io::write_file_atomic(path, encode_png(render_segmentation(grid, w), path.string()));
}

}  // namespace ksmc::stdlib::indoor::io
