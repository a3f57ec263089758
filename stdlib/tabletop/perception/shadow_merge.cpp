#include "stdlib/tabletop/perception/shadow_merge.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>

#include "stdlib/tabletop/perception/footprint.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

using Cell = std::pair<long, long>;
struct CellHash {
  std::size_t operator()(const Cell& c) const noexcept {
    return std::hash<long>()(c.first) * 0x9E3779B97F4A7C15ULL ^ std::hash<long>()(c.second);
  }
};
// Cell tables are looked up, and walked only to count (widest_top): their order does not
// change a result, so they are hashed.
template <class T>
using CellMap = std::unordered_map<Cell, T, CellHash>;

// 2D points hashed on a grid of `cell` m: "is any point within `cell` of q".
class Near2 {
 public:
  explicit Near2(double cell) : cell_(cell) {}
  void add(double x, double y) { cells_[key(x, y)].emplace_back(x, y); }
  [[nodiscard]] bool near(double x, double y) const {
    const Cell k = key(x, y);
    for (long i = -1; i <= 1; ++i)
      for (long j = -1; j <= 1; ++j) {
        const auto it = cells_.find({k.first + i, k.second + j});
        if (it == cells_.end()) continue;
        for (const auto& p : it->second)
          if ((p - Eigen::Vector2d(x, y)).squaredNorm() <= cell_ * cell_) return true;
      }
    return false;
  }
  [[nodiscard]] bool empty() const { return cells_.empty(); }

 private:
  [[nodiscard]] Cell key(double x, double y) const {
    return {std::lround(std::floor(x / cell_)), std::lround(std::floor(y / cell_))};
  }
  double cell_;
  CellMap<std::vector<Eigen::Vector2d>> cells_;
};

constexpr double kCell = 0.005;  // m, the footprint grid of the tops

Cell cell_of(const Eigen::Vector3d& p) {
  return {std::lround(std::floor(p.x() / kCell)), std::lround(std::floor(p.y() / kCell))};
}

// The highest point of each footprint cell.
CellMap<double> cell_tops(const Points& pts) {
  CellMap<double> top;
  for (const auto& p : pts) {
    auto [it, fresh] = top.emplace(cell_of(p), p.z());
    if (!fresh) it->second = std::max(it->second, p.z());
  }
  return top;
}

// Points of a top at height `plane`: within `band` of it and of their cell's highest point
// (a side face crossing that height is not a top).
bool on_top(const Eigen::Vector3d& p, double plane, double band, const CellMap<double>& tops) {
  return std::abs(p.z() - plane) <= band && p.z() >= tops.at(cell_of(p)) - band;
}

// The height of a cluster's widest flat top: the most common highest point over 5 mm cells
// (4 mm bins, the higher bin on a tie).
double widest_top(const CellMap<double>& top) {
  std::map<long, int> hist;
  for (const auto& [k, z] : top) ++hist[std::lround(std::floor(z / 0.004))];
  long best = 0;
  int count = -1;
  for (const auto& [bin, n] : hist)
    if (n >= count) best = bin, count = n;
  return (static_cast<double>(best) + 0.5) * 0.004;
}

struct Bounds {
  Eigen::Vector2d lo{1e9, 1e9}, hi{-1e9, -1e9};
  double top = -1e9;
};

Bounds bounds_of(const Points& pts) {
  Bounds b;
  for (const auto& p : pts) {
    b.lo = b.lo.cwiseMin(p.head<2>());
    b.hi = b.hi.cwiseMax(p.head<2>());
    b.top = std::max(b.top, p.z());
  }
  return b;
}

// True when `far` is the bare far part of a top whose near part, with the box lying on it,
// is `near`: see the header.
bool shadow_split(const Points& near, const CellMap<double>& near_tops, const Points& far, const CellMap<double>& far_tops,
                  double plane, const Eigen::Vector3d& sensor, const ShadowMergeOptions& o) {
  Near2 near_plane(o.reach), shadow(o.reach);
  std::size_t on_plane = 0, above = 0;
  for (const auto& p : near) {
    if (on_top(p, plane, o.plane_band, near_tops)) {
      near_plane.add(p.x(), p.y());
      ++on_plane;
    } else if (p.z() > plane + o.occluder_above && sensor.z() > p.z()) {
      // Where the ray from the sensor through p meets the plane.
      const double t = (sensor.z() - plane) / (sensor.z() - p.z());
      const Eigen::Vector3d q = sensor + t * (p - sensor);
      shadow.add(q.x(), q.y());
      ++above;
    }
  }
  if (on_plane < o.min_points || above < o.min_points) return false;
  bool far_touches = false;
  for (const auto& p : far)
    if (on_top(p, plane, o.plane_band, far_tops) && shadow.near(p.x(), p.y())) {
      far_touches = true;
      break;
    }
  if (!far_touches) return false;
  // The occluder rests on the near top: some of its points are within `reach` (2D) of the
  // top's points.
  for (const auto& p : near)
    if (p.z() > plane + o.occluder_above && near_plane.near(p.x(), p.y())) return true;
  return false;
}

// True when the sensor saw under the plane between the tops: inside the convex hull of both
// tops' points (inset by `slab_inset`), rays crossed the height `slab_top` under the plane and
// ended below the lower half of that height (the table between two boxes, not a box leaning on
// one). One top split by a shadow has no such ray: there, the rays end on the top or on the
// box lying on it.
bool seen_between(const Points& near, const CellMap<double>& near_tops, const Points& far, const CellMap<double>& far_tops,
                  double plane, const RayIndex& rays, const ShadowMergeOptions& o) {
  std::vector<Eigen::Vector2d> tops;
  for (const auto& p : near)
    if (on_top(p, plane, o.plane_band, near_tops)) tops.emplace_back(p.x(), p.y());
  for (const auto& p : far)
    if (on_top(p, plane, o.plane_band, far_tops)) tops.emplace_back(p.x(), p.y());
  const std::vector<Eigen::Vector2d> hull = convex_hull(tops);
  const double cross_at = plane - o.slab_top, end_below = std::min(cross_at - o.slab_depth, 0.5 * cross_at);
  if (hull.size() < 3 || end_below <= 0.0) return false;
  const auto inside_hull = [&hull, &o](const Eigen::Vector2d& q) {
    for (std::size_t k = 0; k < hull.size(); ++k) {
      const Eigen::Vector2d e = hull[(k + 1) % hull.size()] - hull[k], d = q - hull[k];
      if (e.x() * d.y() - e.y() * d.x() < o.slab_inset * e.norm()) return false;  // left of each CCW edge, by the inset
    }
    return true;
  };
  const Obb slab = upright_over(min_area_rect(tops), end_below, cross_at);  // around the hull: which rays to read
  const FreeSpace& seen = rays.free_space();
  const Eigen::Vector3d& s = seen.sensor;
  if (s.z() <= cross_at) return false;
  std::size_t through = 0;
  rays.for_each_toward(slab, [&](std::size_t ray) {
    const Eigen::Vector3d& p = seen.points[ray];
    if (p.z() >= end_below) return;
    const Eigen::Vector3d q = s + (s.z() - cross_at) / (s.z() - p.z()) * (p - s);
    through += inside_hull(q.head<2>());
  });
  const double limit = std::max(static_cast<double>(o.max_seen_through), o.seen_through_share * static_cast<double>(tops.size()));
  return static_cast<double>(through) > limit;
}

}  // namespace

std::vector<Points> merge_shadow_split(std::vector<Points> clusters, const Eigen::Vector3d& sensor,
                                       const ShadowMergeOptions& o, const RayIndex* rays) {
  if (!o.enabled || clusters.size() < 2) return clusters;
  const std::size_t n = clusters.size();
  std::vector<Bounds> bounds;
  std::vector<CellMap<double>> tops;  // each cluster's highest point per footprint cell
  for (const auto& c : clusters) {
    bounds.push_back(bounds_of(c));
    tops.push_back(cell_tops(c));
  }
  std::vector<std::size_t> root(n);
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&root](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t f = 0; f < n; ++f) {
    // The far part is a bare top: nothing of it more than 2 x plane_band above its plane.
    const double plane = widest_top(tops[f]);
    if (bounds[f].top > plane + 2.0 * o.plane_band) continue;
    std::size_t on_plane = 0;
    for (const auto& p : clusters[f]) on_plane += on_top(p, plane, o.plane_band, tops[f]);
    if (on_plane < o.min_points) continue;
    for (std::size_t c = 0; c < n; ++c) {
      if (c == f || find(c) == find(f)) continue;
      const Bounds& a = bounds[c];
      const Bounds& b = bounds[f];
      const Eigen::Vector2d gap = (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0);
      if (gap.norm() > o.neighbourhood || a.top <= plane + o.occluder_above) continue;
      if (!shadow_split(clusters[c], tops[c], clusters[f], tops[f], plane, sensor, o)) continue;
      if (rays != nullptr && seen_between(clusters[c], tops[c], clusters[f], tops[f], plane, *rays, o)) continue;
      root[find(f)] = find(c);
    }
  }
  // Each group in the place of its first cluster; the rest appended to it in order.
  std::vector<Points> out;
  std::map<std::size_t, std::size_t> slot;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = find(i);
    const auto [it, fresh] = slot.emplace(r, out.size());
    if (fresh) out.emplace_back();
    Points& dst = out[it->second];
    dst.insert(dst.end(), clusters[i].begin(), clusters[i].end());
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
