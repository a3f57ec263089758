#include "stdlib/tabletop/perception/cloud_truth.h"

namespace ksmc::stdlib::tabletop::perception {

CloudTruth evaluate_cloud_scene(const CloudScene& cs, const std::vector<TruthBox>& truth, double gate,
                                double surface_gate) {
  CloudTruth out;
  const auto est = camera_frame_boxes(cs.scene);
  out.by_centres = evaluate_registered(est, truth, gate);
  const std::vector<Points> clusters = clusters_in_cloud(cs);
  Points all;
  for (const auto& c : clusters) all.insert(all.end(), c.begin(), c.end());
  const Eigen::Isometry3d start =
      out.by_centres.registration.matched >= 3 ? out.by_centres.registration.source_to_target : Eigen::Isometry3d::Identity();
  out.surfaces = fit_to_box_surfaces(all, truth, start, surface_gate);
  out.by_points = evaluate_matched(est, truth, match_by_points(clusters, truth, out.surfaces.points_to_boxes, surface_gate));
  out.table_in_truth = out.surfaces.points_to_boxes * cs.table.table_in_cloud.isometry();
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
