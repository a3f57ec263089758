#include "stdlib/tabletop/perception/scene_from_cloud.h"

#include <fmt/format.h>

#include "runtime/io/cancel.h"

namespace ksmc::stdlib::tabletop::perception {

CloudScene scene_from_points(const Points& cloud, const std::string& source, const CloudOptions& options) {
  if (cloud.empty()) throw CloudError(fmt::format("{}: empty cloud: no points", source));
  const auto stage = [&options](std::string_view what) {
    runtime::io::throw_if_cancelled(what);
    if (options.stage) options.stage(what);
  };
  CloudScene out;
  out.cloud_points = cloud.size();
  stage(fmt::format("finding the table plane in {} points (RANSAC)", cloud.size()));
  out.table = fit_table(cloud, source, options.table);
  out.cloud_in_table = to_table_frame(cloud, out.table.table_in_cloud);
  out.sensor_in_table = out.table.table_in_cloud.inverse().t;
  stage("clustering the points above the table");
  out.object_points = cluster_objects(out.cloud_in_table, out.table.extent, options.clusters);
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
  std::vector<Points> clusters = std::move(out.object_points);
  out.object_points.clear();
  stage(fmt::format("fitting boxes to {} clusters", clusters.size()));
  ClusterBoxOptions fit = options.fit;
  fit.parts = options.clusters;  // the rest after a tilted box is split as the cloud was
  FreeSpace seen;  // the stacks' free-space test: what the sensor saw through
  seen.points = out.cloud_in_table;
  seen.sensor = out.sensor_in_table;
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const std::vector<UprightBox> boxes = fit_cluster_boxes(clusters[c], fit, &seen);
    for (const UprightBox& box : boxes) {
      SceneObject o;
      o.id = options.id_prefix + std::to_string(s.objects.size());
      o.model = "cluster";
      o.size = box.size;
      o.pose = box.pose;
      // The box's own points: those of the cluster within 1 cm of it (stacked boxes split them).
      const Obb obb = o.obb();
      Points own;
      for (const auto& p : clusters[c])
        if (boxes.size() == 1 || obb.contains(p, 0.01)) own.push_back(p);
      out.object_points.push_back(std::move(own));
      out.cluster_of.push_back(static_cast<int>(c));
      s.objects.push_back(std::move(o));
    }
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
