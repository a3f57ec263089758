#include "stdlib/tabletop/perception/top_parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "stdlib/tabletop/perception/point_grid.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
  return i;
}

// The highest point seen in each cell of a dense grid over the points (NaN: no point).
struct HeightGrid {
  double size = 0.005;
  long x0 = 0, y0 = 0, nx = 0, ny = 0;
  std::vector<double> highest;

  [[nodiscard]] long ix(double x) const { return cell_of(x, size) - x0; }
  [[nodiscard]] long iy(double y) const { return cell_of(y, size) - y0; }
  [[nodiscard]] bool in(long i, long j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
  [[nodiscard]] std::size_t at(long i, long j) const { return static_cast<std::size_t>(j * nx + i); }
  [[nodiscard]] std::size_t at(const Eigen::Vector3d& p) const { return at(ix(p.x()), iy(p.y())); }
};

HeightGrid height_grid(const Points& rest, const Points& top, double size) {
  HeightGrid g;
  g.size = size;
  long x1 = 0, y1 = 0;
  bool first = true;
  for (const Points* pts : {&rest, &top})
    for (const auto& p : *pts) {
      const long i = cell_of(p.x(), size), j = cell_of(p.y(), size);
      if (first) g.x0 = x1 = i, g.y0 = y1 = j, first = false;
      g.x0 = std::min(g.x0, i), x1 = std::max(x1, i), g.y0 = std::min(g.y0, j), y1 = std::max(y1, j);
    }
  g.nx = x1 - g.x0 + 1;
  g.ny = y1 - g.y0 + 1;
  g.highest.assign(static_cast<std::size_t>(g.nx * g.ny), std::numeric_limits<double>::quiet_NaN());
  for (const Points* pts : {&rest, &top})  // `top` is normally within `rest`; a caller's extra points count too
    for (const auto& p : *pts) {
      double& h = g.highest[g.at(p)];
      if (std::isnan(h) || p.z() > h) h = p.z();
    }
  return g;
}

}  // namespace

std::vector<Points> top_parts(const Points& top, const Points& rest, double above, const TopPartOptions& o) {
  if (top.empty()) return {};
  // A cell is part of a top when its highest point is above `above`, seen lower when it is not.
  const HeightGrid g = height_grid(rest, top, o.cell);
  const auto is_top = [&](long i, long j) {
    if (!g.in(i, j)) return false;
    const double h = g.highest[g.at(i, j)];
    return !std::isnan(h) && h > above;
  };
  // Connected parts (8-neighbours) of the top cells.
  std::vector<int> part_of(g.highest.size(), -1);
  int parts = 0;
  for (long j = 0; j < g.ny; ++j)
    for (long i = 0; i < g.nx; ++i) {
      if (!is_top(i, j) || part_of[g.at(i, j)] >= 0) continue;
      std::vector<std::pair<long, long>> queue{{i, j}};
      part_of[g.at(i, j)] = parts;
      while (!queue.empty()) {
        const auto [qi, qj] = queue.back();
        queue.pop_back();
        for (long dx = -1; dx <= 1; ++dx)
          for (long dy = -1; dy <= 1; ++dy) {
            const long ni = qi + dx, nj = qj + dy;
            if (!is_top(ni, nj) || part_of[g.at(ni, nj)] >= 0) continue;
            part_of[g.at(ni, nj)] = parts;
            queue.emplace_back(ni, nj);
          }
      }
      ++parts;
    }
  if (parts <= 1) return {top};
  const auto n = static_cast<std::size_t>(parts);
  std::vector<std::size_t> count(n, 0);
  std::vector<Eigen::Vector2d> centre(n, Eigen::Vector2d::Zero());
  std::vector<int> label(top.size());
  for (std::size_t i = 0; i < top.size(); ++i) {
    const int k = part_of[g.at(top[i])];
    label[i] = k;
    ++count[static_cast<std::size_t>(k)];
    centre[static_cast<std::size_t>(k)] += top[i].head<2>();
  }
  for (std::size_t k = 0; k < n; ++k) centre[k] /= static_cast<double>(count[k]);  // every part holds a top point
  // Cells seen lower on the segment between two parts' centres.
  const auto lower_between = [&](std::size_t a, std::size_t b) {
    const Eigen::Vector2d d = centre[b] - centre[a];
    const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * d.norm() / o.cell)));
    int lower = 0;
    long last_i = 0, last_j = 0;
    bool any = false;
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector2d p = centre[a] + (static_cast<double>(s) / steps) * d;
      const long i = g.ix(p.x()), j = g.iy(p.y());
      if (any && i == last_i && j == last_j) continue;
      last_i = i, last_j = j, any = true;
      if (!g.in(i, j)) continue;
      const double h = g.highest[g.at(i, j)];
      if (!std::isnan(h) && h <= above) ++lower;
    }
    return lower;
  };
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (lower_between(a, b) < o.min_lower_cells)
        parent[static_cast<std::size_t>(root(parent, static_cast<int>(a)))] = root(parent, static_cast<int>(b));
  // Groups; a group with too few points joins the group whose centre is nearest.
  std::vector<std::size_t> group_count(n, 0);
  for (std::size_t k = 0; k < n; ++k) group_count[static_cast<std::size_t>(root(parent, static_cast<int>(k)))] += count[k];
  std::vector<std::size_t> big;
  for (std::size_t k = 0; k < n; ++k)
    if (root(parent, static_cast<int>(k)) == static_cast<int>(k) && group_count[k] >= o.min_points) big.push_back(k);
  if (big.size() <= 1) return {top};
  std::vector<std::size_t> home(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto group = static_cast<std::size_t>(root(parent, static_cast<int>(k)));
    if (group_count[group] >= o.min_points) {
      home[k] = group;
      continue;
    }
    home[k] = *std::min_element(big.begin(), big.end(), [&](std::size_t x, std::size_t y) {
      return (centre[x] - centre[k]).squaredNorm() < (centre[y] - centre[k]).squaredNorm();
    });
  }
  std::map<std::size_t, std::size_t> index;  // group -> output position, by first point
  std::vector<Points> out;
  for (std::size_t i = 0; i < top.size(); ++i) {
    const std::size_t group = home[static_cast<std::size_t>(label[i])];
    const auto [it, fresh] = index.emplace(group, out.size());
    if (fresh) out.emplace_back();
    out[it->second].push_back(top[i]);
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
