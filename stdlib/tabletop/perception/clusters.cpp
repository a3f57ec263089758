#include "stdlib/tabletop/perception/clusters.h"

#include <algorithm>
#include <cmath>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

namespace ksmc::stdlib::tabletop::perception {

std::vector<Points> cluster_objects(const Points& table_points, const Eigen::Vector2d& extent,
                                    const ClusterOptions& options) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr above(new pcl::PointCloud<pcl::PointXYZ>);
  Points kept;
  for (const auto& p : table_points) {
    if (p.z() < options.min_height || p.z() > options.max_height) continue;
    if (std::abs(p.x()) > 0.5 * extent.x() + options.table_margin) continue;
    if (std::abs(p.y()) > 0.5 * extent.y() + options.table_margin) continue;
    kept.push_back(p);
    above->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));
  }
  std::vector<Points> out;
  if (above->empty()) return out;

  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(above);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> ec;
  ec.setClusterTolerance(options.tolerance);
  ec.setMinClusterSize(static_cast<pcl::uindex_t>(options.min_points));
  ec.setMaxClusterSize(static_cast<pcl::uindex_t>(std::min<std::size_t>(options.max_points, 0x7fffffff)));
  ec.setSearchMethod(tree);
  ec.setInputCloud(above);
  std::vector<pcl::PointIndices> found;
  ec.extract(found);

  for (const auto& c : found) {
    std::vector<int> idx(c.indices.begin(), c.indices.end());
    std::sort(idx.begin(), idx.end());  // input order inside a cluster
    Points pts;
    pts.reserve(idx.size());
    for (int i : idx) pts.push_back(kept[static_cast<std::size_t>(i)]);
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

}  // namespace ksmc::stdlib::tabletop::perception
