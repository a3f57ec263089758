#include "stdlib/tabletop/perception/point_grid.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ksmc::stdlib::tabletop::perception {

PointGrid::PointGrid(const Points& points, double radius) : points_(points), radius_(radius) {
  cells_.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    cells_.emplace_back(key(cell_of(p.x(), radius), cell_of(p.y(), radius), cell_of(p.z(), radius)), static_cast<int>(i));
  }
  std::sort(cells_.begin(), cells_.end());
  if (points.empty()) return;
  long x1 = x0_ = cell_of(points[0].x(), radius), y1 = y0_ = cell_of(points[0].y(), radius);
  for (const auto& p : points) {
    const long x = cell_of(p.x(), radius), y = cell_of(p.y(), radius);
    x0_ = std::min(x0_, x), x1 = std::max(x1, x), y0_ = std::min(y0_, y), y1 = std::max(y1, y);
  }
  nx_ = x1 - x0_ + 1, ny_ = y1 - y0_ + 1;
  // The column table only where it is about as small as the points (a sparse wide cloud
  // keeps the binary search).
  if (static_cast<double>(nx_) * static_cast<double>(ny_) > 4.0 * static_cast<double>(points.size()) + 65536.0) return;
  constexpr long kHalf = 1L << 20;  // keys wrap outside [-2^20, 2^20) cells: no column order to follow
  if (x0_ < -kHalf || x1 >= kHalf || y0_ < -kHalf || y1 >= kHalf) return;
  column_start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  // Keys order the cells by x, then y, then z: the columns follow each other in that order.
  std::size_t k = 0;
  for (long c = 0; c < nx_ * ny_; ++c) {
    column_start_[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(k);
    const std::uint64_t column = key(x0_ + c / ny_, y0_ + c % ny_, 0) >> 21;
    while (k < cells_.size() && (cells_[k].first >> 21) == column) ++k;
  }
  column_start_.back() = static_cast<std::uint32_t>(k);
  if (k != cells_.size()) column_start_.clear();  // not in column order after all: the binary search
}

std::uint64_t PointGrid::key(long x, long y, long z) const {
  // 21 bits per axis (offset): +-10 km at 1 cm cells, far beyond any table.
  const auto u = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & ((1ULL << 21) - 1); };
  return (u(x) << 42) | (u(y) << 21) | u(z);
}

void PointGrid::neighbours(const Eigen::Vector3d& p, std::vector<int>& out) const { within(p, radius_, out); }

void PointGrid::within(const Eigen::Vector3d& p, double radius, std::vector<int>& out) const {
  out.clear();
  const long cx = cell_of(p.x(), radius_), cy = cell_of(p.y(), radius_), cz = cell_of(p.z(), radius_);
  const long reach = std::max(1L, std::lround(std::ceil(radius / radius_)));
  const double r2 = radius * radius;
  // The cells along z of one (x, y) column are adjacent in key order: one search each.
  for (long dx = -reach; dx <= reach; ++dx)
    for (long dy = -reach; dy <= reach; ++dy) {
      const std::uint64_t first = key(cx + dx, cy + dy, cz - reach), last = key(cx + dx, cy + dy, cz + reach);
      auto begin = cells_.begin(), end = cells_.end();
      if (!column_start_.empty()) {
        const long x = cx + dx - x0_, y = cy + dy - y0_;
        if (x < 0 || x >= nx_ || y < 0 || y >= ny_) continue;
        const auto c = static_cast<std::size_t>(x * ny_ + y);
        begin = cells_.begin() + column_start_[c];
        end = cells_.begin() + column_start_[c + 1];
      }
      for (auto it = std::lower_bound(begin, end, std::make_pair(first, -1)); it != end && it->first <= last; ++it)
        if ((points_[static_cast<std::size_t>(it->second)] - p).squaredNorm() <= r2) out.push_back(it->second);
    }
}

Points voxel_subsample(const Points& points, double voxel) {
  std::vector<std::pair<std::array<long, 3>, std::size_t>> cells;
  cells.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    cells.push_back({{cell_of(points[i].x(), voxel), cell_of(points[i].y(), voxel), cell_of(points[i].z(), voxel)}, i});
  std::sort(cells.begin(), cells.end());
  std::vector<std::size_t> keep;
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (k == 0 || cells[k].first != cells[k - 1].first) keep.push_back(cells[k].second);
  std::sort(keep.begin(), keep.end());
  Points out;
  out.reserve(keep.size());
  for (std::size_t i : keep) out.push_back(points[i]);
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
