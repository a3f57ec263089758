#include "stdlib/tabletop/perception/scene_from_cloud.h"

#include <fmt/format.h>

namespace ksmc::stdlib::tabletop::perception {

CloudScene scene_from_points(const Points& cloud, const std::string& source, const CloudOptions& options) {
  if (cloud.empty()) throw CloudError(fmt::format("{}: empty cloud: no points", source));
  CloudScene out;
  out.cloud_points = cloud.size();
  out.table = fit_table(cloud, source, options.table);
  const Points local = to_table_frame(cloud, out.table.table_in_cloud);
  out.object_points = cluster_objects(local, out.table.extent, options.clusters);
  if (out.object_points.empty())
    throw CloudError(fmt::format("{}: no object above the table ({} table points, none of the other {} points "
                                 "forms a cluster of {} points between {} and {} m above it)",
                                 source, out.table.inliers, cloud.size() - out.table.inliers,
                                 options.clusters.min_points, options.clusters.min_height,
                                 options.clusters.max_height));

  Scene& s = out.scene;
  s.camera = options.camera;
  s.table_in_camera = out.table.table_in_cloud;
  s.table.size = Eigen::Vector3d(out.table.extent.x(), out.table.extent.y(), options.table_thickness);
  for (std::size_t i = 0; i < out.object_points.size(); ++i) {
    const UprightBox box = fit_upright_box(out.object_points[i], options.box);
    SceneObject o;
    o.id = options.id_prefix + std::to_string(i);
    o.model = "cluster";
    o.size = box.size;
    o.pose = box.pose;
    s.objects.push_back(std::move(o));
  }
  return out;
}

std::vector<Points> clusters_in_cloud(const CloudScene& cs) {
  const Eigen::Isometry3d t = cs.table.table_in_cloud.isometry();
  std::vector<Points> out;
  for (const auto& cluster : cs.object_points) {
    Points& o = out.emplace_back();
    for (const auto& p : cluster) o.push_back(t * p);
  }
  return out;
}

CloudScene scene_from_cloud(const std::filesystem::path& path, const CloudOptions& options) {
  return scene_from_points(load_cloud(path, options.units), path.string(), options);
}

}  // namespace ksmc::stdlib::tabletop::perception
