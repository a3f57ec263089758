#include "stdlib/tabletop/perception/top_parts.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace ksmc::stdlib::tabletop::perception {

namespace {

using Cell = std::pair<long, long>;

Cell cell_of(double x, double y, double size) {
  return {std::lround(std::floor(x / size)), std::lround(std::floor(y / size))};
}

int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
  return i;
}

}  // namespace

std::vector<Points> top_parts(const Points& top, const Points& rest, double above, const TopPartOptions& o) {
  if (top.empty()) return {};
  // The highest point seen in each cell: a cell is part of a top when it is above `above`, seen
  // lower when its highest point is not.
  std::map<Cell, double> highest;
  for (const auto& p : rest) {
    auto [it, fresh] = highest.emplace(cell_of(p.x(), p.y(), o.cell), p.z());
    if (!fresh) it->second = std::max(it->second, p.z());
  }
  for (const auto& p : top) {  // `top` is normally within `rest`; a caller's extra points count too
    auto [it, fresh] = highest.emplace(cell_of(p.x(), p.y(), o.cell), p.z());
    if (!fresh) it->second = std::max(it->second, p.z());
  }
  // Connected parts (8-neighbours) of the top cells.
  std::map<Cell, int> part_of;
  int parts = 0;
  for (const auto& [c, h] : highest) {
    if (h <= above || part_of.count(c) != 0) continue;
    std::vector<Cell> queue{c};
    part_of[c] = parts;
    while (!queue.empty()) {
      const Cell q = queue.back();
      queue.pop_back();
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy) {
          const Cell n{q.first + dx, q.second + dy};
          const auto it = highest.find(n);
          if (it == highest.end() || it->second <= above || part_of.count(n) != 0) continue;
          part_of[n] = parts;
          queue.push_back(n);
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
    const int k = part_of.at(cell_of(top[i].x(), top[i].y(), o.cell));
    label[i] = k;
    ++count[static_cast<std::size_t>(k)];
    centre[static_cast<std::size_t>(k)] += top[i].head<2>();
  }
  for (std::size_t k = 0; k < n; ++k)
    if (count[k] > 0) centre[k] /= static_cast<double>(count[k]);
  // Cells seen lower on the segment between two parts' centres.
  const auto lower_between = [&](std::size_t a, std::size_t b) {
    const Eigen::Vector2d d = centre[b] - centre[a];
    const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * d.norm() / o.cell)));
    int lower = 0;
    Cell last{0, 0};
    bool any = false;
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector2d p = centre[a] + (static_cast<double>(s) / steps) * d;
      const Cell c = cell_of(p.x(), p.y(), o.cell);
      if (any && c == last) continue;
      last = c;
      any = true;
      const auto it = highest.find(c);
      if (it != highest.end() && it->second <= above) ++lower;
    }
    return lower;
  };
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (count[a] > 0 && count[b] > 0 && lower_between(a, b) < o.min_lower_cells)
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
    const auto g = static_cast<std::size_t>(root(parent, static_cast<int>(k)));
    if (group_count[g] >= o.min_points) {
      home[k] = g;
      continue;
    }
    home[k] = *std::min_element(big.begin(), big.end(), [&](std::size_t x, std::size_t y) {
      return (centre[x] - centre[k]).squaredNorm() < (centre[y] - centre[k]).squaredNorm();
    });
  }
  std::map<std::size_t, std::size_t> index;  // group -> output position, by first point
  std::vector<Points> out;
  for (std::size_t i = 0; i < top.size(); ++i) {
    const std::size_t g = home[static_cast<std::size_t>(label[i])];
    const auto [it, fresh] = index.emplace(g, out.size());
    if (fresh) out.emplace_back();
    out[it->second].push_back(top[i]);
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
