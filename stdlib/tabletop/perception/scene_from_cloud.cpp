#include "stdlib/tabletop/perception/scene_from_cloud.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "runtime/io/cancel.h"
#include "stdlib/tabletop/perception/own_points.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

// A point count set on a cloud `rho` times denser: it shrinks by rho^2 (at least 3).
std::size_t fewer_points(std::size_t n, double rho) {
  return std::max<std::size_t>(3, static_cast<std::size_t>(std::lround(static_cast<double>(n) / (rho * rho))));
}

// The box fits' sampling-dependent settings for a cloud `rho` times sparser than the one
// they were set on (rho = derived / floor clustering tolerance, >= 1): neighbourhood radii
// and cells grow by rho, point counts shrink by rho^2.
ClusterBoxOptions for_sampling(ClusterBoxOptions fit, double rho) {
  if (rho <= 1.0) return fit;
  const auto fewer = [rho](std::size_t n) { return fewer_points(n, rho); };
  fit.tilt.faces.normal_radius *= rho;
  fit.tilt.faces.grow_radius *= rho;
  fit.tilt.faces.min_points = fewer(fit.tilt.faces.min_points);
  fit.tilt.min_face_points = fewer(fit.tilt.min_face_points);
  fit.tilt.own_margin *= rho;
  fit.tilt.edge_gap *= rho;
  fit.tilt.fill_cell *= rho;
  fit.tilt.probe_voxel *= rho;
  fit.box.wall_voxel *= rho;
  fit.stacks.cell *= rho;
  fit.stacks.column_margin *= rho;
  fit.stacks.min_points = fewer(fit.stacks.min_points);
  fit.stacks.sides.min_top_points = fewer(fit.stacks.sides.min_top_points);
  fit.stacks.sides.min_bin_points = fewer(fit.stacks.sides.min_bin_points);
  return fit;
}

}  // namespace

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
  ClusterOptions clusters_options = options.clusters;
  const AboveTable above(out.cloud_in_table, out.table.extent, options.clusters);  // one KD-tree for both
  if (options.clusters.spacing_factor > 0.0) {  // a sparser cloud (resolution, range, voxel filter) needs more
    out.point_spacing = above.spacing();
    clusters_options.tolerance = std::max(options.clusters.tolerance, options.clusters.spacing_factor * out.point_spacing);
  }
  out.cluster_tolerance = clusters_options.tolerance;
  stage(fmt::format("clustering the points above the table ({:.1f} mm tolerance)", 1000.0 * clusters_options.tolerance));
  FreeSpace seen;  // what the sensor saw through: the shadow merge's, the stacks' and the passes' ray tests
  seen.points = out.cloud_in_table;
  seen.sensor = out.sensor_in_table;
  const RayIndex rays(std::move(seen));  // each test reads only the rays toward its box
  out.object_points = merge_shadow_split(above.clusters(clusters_options, out.sensor_in_table), out.sensor_in_table,
                                         options.shadow, &rays);
  if (out.object_points.empty())
    throw CloudError(fmt::format("{}: no object above the table ({} table points, none of the other {} points "
                                 "forms a cluster of {} points between {} and {} m above it)",
                                 source, out.table.inliers, cloud.size() - out.table.inliers,
                                 clusters_options.min_points, clusters_options.min_height,
                                 clusters_options.max_height));

  Scene& s = out.scene;
  s.camera = options.camera;
  s.table_in_camera = out.table.table_in_cloud;
  s.table.size = Eigen::Vector3d(out.table.extent.x(), out.table.extent.y(), options.table_thickness);
  // The depth noise near the objects, as the table plane shows it; to the micrometre, as
  // scene.json writes it, so that `tabletop DIR/scene.json` derives the same tolerances.
  s.depth_noise = std::round(out.table.noise * 1e6) / 1e6;
  std::vector<Points> clusters = std::move(out.object_points);
  out.object_points.clear();
  stage(fmt::format("fitting boxes to {} clusters", clusters.size()));
  ClusterBoxOptions fit = options.fit;
  if (options.clusters.tolerance > 0.0) fit = for_sampling(fit, clusters_options.tolerance / options.clusters.tolerance);
  fit.parts = clusters_options;  // the rest after a tilted box is split as the cloud was
  std::vector<UprightBox> boxes;  // all clusters' boxes, then the hidden feet grown
  std::vector<std::size_t> cluster_of, per_cluster(clusters.size(), 0);
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    for (const UprightBox& box : fit_cluster_boxes(clusters[c], fit, &rays)) {
      boxes.push_back(box);
      cluster_of.push_back(c);
      ++per_cluster[c];
    }
  }
  // A box's own points (own_points.h); the layers of a stack kept apart by 3 x the depth
  // noise.
  OwnPointsOptions owned;
  owned.layer_margin = 3.0 * out.table.noise;
  const auto points_of = [&](std::size_t i) { return own_points(boxes, cluster_of, i, clusters[cluster_of[i]], owned); };
  SeenUnderOptions under = options.seen_under;
  // A noisier cloud puts the points near a box's edges farther out: the footprint is inset by
  // noise_inset x the table plane's RMS when that is more.
  under.inset = std::max(under.inset, under.noise_inset * out.table.rms);
  HiddenBottomOptions hidden = options.hidden_bottom;
  OccludedGapOptions gap = options.occluded_gap;
  HiddenReachOptions reach = options.hidden_reach;
  TiltedFootOptions foot = options.tilted_foot;
  if (options.clusters.tolerance > 0.0 && clusters_options.tolerance > options.clusters.tolerance) {
    const double rho = clusters_options.tolerance / options.clusters.tolerance;
    under.min_rays = fewer_points(under.min_rays, rho);
    under.min_points = fewer_points(under.min_points, rho);
    hidden.min_rays = fewer_points(hidden.min_rays, rho);
    reach.min_rays = fewer_points(reach.min_rays, rho);
    gap.min_rays = fewer_points(gap.min_rays, rho);
    foot.min_rays = fewer_points(foot.min_rays, rho);
  }
  for (std::size_t i = 0; i < boxes.size(); ++i) {  // boxes the sensor saw under are cut
    const std::size_t c = cluster_of[i];
    const std::vector<UprightBox> parts =
        cut_seen_under(boxes[i], points_of(i), rays, fit.box, fit.stacks.sides, under);
    if (parts.empty()) continue;
    const auto at = static_cast<std::ptrdiff_t>(i);
    boxes.erase(boxes.begin() + at);
    boxes.insert(boxes.begin() + at, parts.begin(), parts.end());
    cluster_of.insert(cluster_of.begin() + at, parts.size() - 1, c);
    per_cluster[c] += parts.size() - 1;
    i += parts.size() - 1;
  }
  grow_hidden_bottoms(boxes, rays, fit.box.float_gap, hidden);
  grow_hidden_reach(boxes, rays, reach);
  grow_tilted_feet(boxes, rays, foot);
  // Box j goes into box i: it is removed, and its points become box i's cluster's when it was
  // its own cluster's only box.
  const auto drop_into = [&](std::size_t j, std::size_t i) {
    const std::size_t ci = cluster_of[i], cj = cluster_of[j];
    if (ci != cj && per_cluster[cj] == 1) {
      clusters[ci].insert(clusters[ci].end(), clusters[cj].begin(), clusters[cj].end());
      clusters[cj].clear();
    }
    --per_cluster[cj];
    boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
    cluster_of.erase(cluster_of.begin() + static_cast<std::ptrdiff_t>(j));
  };
  // The two ends of a box something lies across become one box (and one cluster, when each
  // end was a cluster of its own).
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const std::size_t ci = cluster_of[i], cj = cluster_of[j];
      if (ci != cj && (per_cluster[ci] != 1 || per_cluster[cj] != 1)) continue;
      const std::optional<UprightBox> one = bridge_occluded_gap(boxes[i], boxes[j], rays, gap);
      if (!one) continue;
      boxes[i] = *one;
      drop_into(j, i);
      j = i;  // the longer box may reach one more
    }
  }
  // A thin box whose points lie on a larger box is a strip of its face (face_strip.h).
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (!is_thin(boxes[j], options.face_strip)) continue;
    const Points own = points_of(j);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (i == j || !is_face_strip(boxes[j], own, boxes[i], options.face_strip)) continue;
      drop_into(j, i);
      --j;  // the next box is at j now
      break;
    }
  }
  {  // a tilted box does not cut into the upright box it leans on (lean_seat.h)
    std::vector<Points> own(boxes.size());  // only a tilted box's points are read
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (!is_upright(boxes[i])) own[i] = points_of(i);
    seat_leaning_boxes(boxes, own, options.lean_seat);
  }
  OwnPointsOptions observed = owned;  // the cloud likelihood's points: each to its nearest box
  observed.nearest = true;
  observed.not_below = true;  // ... and none seen under it (a box it hides)
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::size_t c = cluster_of[i];
    SceneObject o;
    o.id = options.id_prefix + std::to_string(s.objects.size());
    o.model = "cluster";
    o.size = boxes[i].size;
    o.pose = boxes[i].pose;
    out.object_points.push_back(own_points(boxes, cluster_of, i, clusters[c], observed));
    out.cluster_of.push_back(static_cast<int>(c));
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
