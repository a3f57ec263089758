#include "stdlib/tabletop/perception/surface_registration.h"

#include <algorithm>
#include <cmath>

#include "stdlib/tabletop/perception/registration.h"

namespace ksmc::stdlib::tabletop::perception {

Eigen::Vector3d closest_surface_point(const TruthBox& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d h = 0.5 * box.size;
  Eigen::Vector3d local = box.axes.transpose() * (p - box.centre);
  const Eigen::Vector3d excess = local.cwiseAbs() - h;
  if (excess.maxCoeff() > 0.0) {
    local = local.cwiseMax(-h).cwiseMin(h);
  } else {  // inside: push out through the nearest face
    Eigen::Index k = 0;
    excess.maxCoeff(&k);
    local[k] = local[k] < 0.0 ? -h[k] : h[k];
  }
  return box.centre + box.axes * local;
}

int nearest_box(const std::vector<TruthBox>& boxes, const Eigen::Vector3d& p, double max_distance) {
  int which = -1;
  double best = max_distance;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const double d = (closest_surface_point(boxes[b], p) - p).norm();
    if (d < best) best = d, which = static_cast<int>(b);
  }
  return which;
}

Registration match_by_points(const std::vector<Points>& clusters, const std::vector<TruthBox>& boxes,
                             const Eigen::Isometry3d& transform, double max_distance) {
  std::vector<std::vector<int>> count(boxes.size(), std::vector<int>(clusters.size(), 0));
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (const auto& p : clusters[c]) {
      const int b = nearest_box(boxes, transform * p, max_distance);
      if (b >= 0) ++count[static_cast<std::size_t>(b)][c];
    }
  // Greedy on the counts, largest first: each box and each cluster used once.
  struct Cell {
    int n;
    std::size_t b, c;
  };
  std::vector<Cell> cells;
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for (std::size_t c = 0; c < clusters.size(); ++c)
      if (count[b][c] > 0) cells.push_back({count[b][c], b, c});
  std::sort(cells.begin(), cells.end(), [](const Cell& x, const Cell& y) {
    return x.n > y.n || (x.n == y.n && (x.b < y.b || (x.b == y.b && x.c < y.c)));
  });
  Registration r;
  r.source_to_target = transform;
  r.match.assign(clusters.size(), -1);
  std::vector<bool> box_used(boxes.size(), false);
  for (const Cell& cell : cells) {
    if (box_used[cell.b] || r.match[cell.c] >= 0) continue;
    box_used[cell.b] = true;
    r.match[cell.c] = static_cast<int>(cell.b);
    ++r.matched;
  }
  return r;
}

SurfaceFit fit_to_box_surfaces(const Points& points, const std::vector<TruthBox>& boxes, const Eigen::Isometry3d& initial,
                               double max_distance, int iterations) {
  SurfaceFit fit;
  fit.points_to_boxes = initial;
  for (int it = 0; it <= iterations; ++it) {
    std::vector<Eigen::Vector3d> src, dst;
    double ss = 0.0;
    for (const auto& p : points) {
      const Eigen::Vector3d q = fit.points_to_boxes * p;
      const int b = nearest_box(boxes, q, max_distance);
      if (b < 0) continue;
      const Eigen::Vector3d c = closest_surface_point(boxes[static_cast<std::size_t>(b)], q);
      const double best = (c - q).norm();
      src.push_back(p);
      dst.push_back(c);
      ss += best * best;
    }
    fit.kept = src.size();
    fit.rms = src.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(src.size()));
    if (it == iterations || src.size() < 3) break;
    fit.points_to_boxes = rigid_fit(src, dst);
  }
  return fit;
}

}  // namespace ksmc::stdlib::tabletop::perception
