#include "stdlib/tabletop/perception/clusters.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "runtime/io/cancel.h"

namespace ksmc::stdlib::tabletop::perception {

struct AboveTable::Index {
  Index(Points kept, double cell) : points(std::move(kept)), grid(points, cell) {}
  Index(const Index&) = delete;  // the grid refers to `points`
  Index& operator=(const Index&) = delete;
  Points points;   // the points above the table, in input order
  PointGrid grid;  // over `points`, cells of the floor tolerance
};

AboveTable::AboveTable(const Points& table_points, const Eigen::Vector2d& extent, const ClusterOptions& options) {
  Points kept;
  for (const auto& p : table_points) {
    if (p.z() < options.min_height || p.z() > options.max_height) continue;
    if (std::abs(p.x()) > 0.5 * extent.x() + options.table_margin) continue;
    if (std::abs(p.y()) > 0.5 * extent.y() + options.table_margin) continue;
    kept.push_back(p);
  }
  index_ = std::make_shared<const Index>(std::move(kept), std::max(options.tolerance, 1e-4));
}

const Points& AboveTable::points() const noexcept { return index_->points; }

double AboveTable::median_nearest(std::size_t max_queries, const std::function<double(std::size_t)>& scale) const {
  const Points& pts = index_->points;
  const std::size_t n = pts.size();
  if (n < 2 || max_queries == 0) return 0.0;
  const std::size_t step = std::max<std::size_t>(1, n / max_queries);
  std::vector<int> near;
  std::vector<double> values;
  for (std::size_t i = 0; i < n; i += step) {
    // The nearest other point: the grid's cells first, then twice as far, up to 1 m.
    double best = std::numeric_limits<double>::infinity();
    for (double r = index_->grid.radius(); r <= 1.0 && !std::isfinite(best); r *= 2.0) {
      index_->grid.within(pts[i], r, near);
      for (int j : near)
        if (static_cast<std::size_t>(j) != i) best = std::min(best, (pts[static_cast<std::size_t>(j)] - pts[i]).norm());
    }
    if (std::isfinite(best)) values.push_back(best * scale(i));
  }
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

double AboveTable::spacing(std::size_t max_queries) const {
  return median_nearest(max_queries, [](std::size_t) { return 1.0; });
}

std::vector<Points> AboveTable::clusters(const ClusterOptions& options) const {
  ClusterOptions isotropic = options;
  isotropic.slant_factor = 0.0;
  return clusters(isotropic, Eigen::Vector3d::Zero());
}

std::vector<Points> AboveTable::clusters(const ClusterOptions& options, const Eigen::Vector3d& sensor) const {
  std::vector<Points> out;
  const Points& kept = index_->points;
  const std::size_t n = kept.size();
  if (n == 0) return out;
  // Cells of about the tolerance: a derived tolerance well above the floor gets a grid of its own.
  std::optional<PointGrid> own;
  if (options.tolerance > 1.5 * index_->grid.radius()) own.emplace(kept, options.tolerance);
  const PointGrid& grid = own ? *own : index_->grid;
  // Per point: the horizontal direction of its ray and how far apart the rows of a flat top
  // are along it there (at least the tolerance).
  const bool slant = options.slant_factor > 0.0;
  std::vector<Eigen::Vector2d> along(slant ? n : 0);
  std::vector<double> row(slant ? n : 0, options.tolerance);
  if (slant) {
    // The sensor's angular step: the median nearest-neighbour distance over the range.
    const double step =
        median_nearest(4000, [&](std::size_t i) { return 1.0 / std::max(1e-3, (kept[i] - sensor).norm()); });
    const double cap = options.max_slant * options.tolerance;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d ray = kept[i] - sensor;
      const double r = ray.norm();
      const Eigen::Vector2d h(ray.x(), ray.y());
      if (r <= 0.0 || h.norm() <= 1e-9) continue;
      along[i] = h.normalized();
      const double cos_z = std::max(1e-3, std::abs(ray.z()) / r);
      row[i] = std::clamp(options.slant_factor * r * step / cos_z, options.tolerance, cap);
    }
  }
  const auto joined = [&](std::size_t i, std::size_t j, double squared) {
    if (!slant) return true;
    const Eigen::Vector3d d = kept[j] - kept[i];
    const double l = std::min(row[i], row[j]);
    // Along the horizontal direction of the ray to the pair's midpoint: symmetric in i and j,
    // so the clusters are the connected components of one graph, whatever the search order.
    Eigen::Vector2d w = along[i] + along[j];
    const double tol2 = options.tolerance * options.tolerance;
    if (w.norm() <= 1e-9) return squared <= tol2;  // straight below the sensor: no direction
    w.normalize();
    const double a = d.x() * w.x() + d.y() * w.y();
    const double rest2 = std::max(0.0, squared - a * a);
    return (a * a) / (l * l) + rest2 / tol2 <= 1.0;
  };

  // Euclidean clustering: the connected components of the graph joining points closer than
  // the tolerance (or along a grazing top's rows), grown from each point not yet reached.
  // A cancel request is seen every few thousand searches: on a dense cloud the searches take
  // most of the front end's time.
  std::vector<char> reached(n, 0);
  std::vector<int> neighbours;
  std::vector<int> component;
  std::size_t searches = 0;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (reached[seed]) continue;
    reached[seed] = 1;
    component.assign(1, static_cast<int>(seed));
    for (std::size_t k = 0; k < component.size(); ++k) {
      if (++searches % 4096 == 0) runtime::io::throw_if_cancelled("the clustering of the points above the table");
      const auto i = static_cast<std::size_t>(component[k]);
      // The joined points lie within the larger semi-axis of the ellipse: row[i].
      grid.within(kept[i], slant ? row[i] : options.tolerance, neighbours);
      for (const int j : neighbours) {
        const auto u = static_cast<std::size_t>(j);
        if (!reached[u] && joined(i, u, (kept[u] - kept[i]).squaredNorm())) {
          reached[u] = 1;
          component.push_back(j);
        }
      }
    }
    if (component.size() < options.min_points || component.size() > options.max_points) continue;
    std::sort(component.begin(), component.end());  // input order inside a cluster
    Points pts;
    pts.reserve(component.size());
    for (int i : component) pts.push_back(kept[static_cast<std::size_t>(i)]);
    out.push_back(std::move(pts));
  }
  auto centroid = [](const Points& pts) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (const auto& p : pts) s += p;
    return Eigen::Vector3d(s / static_cast<double>(pts.size()));
  };
  std::vector<std::pair<Eigen::Vector3d, std::size_t>> order;
  for (std::size_t i = 0; i < out.size(); ++i) order.emplace_back(centroid(out[i]), i);
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first.x() < b.first.x() || (a.first.x() == b.first.x() && a.first.y() < b.first.y());
  });
  std::vector<Points> sorted;
  sorted.reserve(out.size());
  for (const auto& [c, i] : order) sorted.push_back(std::move(out[i]));
  return sorted;
}

double object_point_spacing(const Points& table_points, const Eigen::Vector2d& extent, const ClusterOptions& options,
                            std::size_t max_queries) {
  return AboveTable(table_points, extent, options).spacing(max_queries);
}

std::vector<Points> cluster_objects(const Points& table_points, const Eigen::Vector2d& extent,
                                    const ClusterOptions& options) {
  return AboveTable(table_points, extent, options).clusters(options);
}

}  // namespace ksmc::stdlib::tabletop::perception
