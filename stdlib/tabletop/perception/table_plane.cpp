#include "stdlib/tabletop/perception/table_plane.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/console/print.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "stdlib/tabletop/perception/footprint.h"

namespace ksmc::stdlib::tabletop::perception {

Points to_table_frame(const Points& cloud, const Pose& table_in_cloud) {
  const Pose inv = table_in_cloud.inverse();
  const Eigen::Matrix3d r = inv.rotation();
  Points out;
  out.reserve(cloud.size());
  for (const auto& p : cloud) out.push_back(r * p + inv.t);
  return out;
}

TableFit fit_table(const Points& cloud, const std::string& source, const TableOptions& options) {
  if (cloud.size() < 3) throw CloudError(fmt::format("{}: no table plane: only {} points", source, cloud.size()));
  pcl::PointCloud<pcl::PointXYZ>::Ptr pc(new pcl::PointCloud<pcl::PointXYZ>);
  pc->reserve(cloud.size());
  for (const auto& p : cloud)
    pc->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())));

  pcl::SACSegmentation<pcl::PointXYZ> seg;  // fixed-seed sampling: deterministic
  seg.setOptimizeCoefficients(true);
  seg.setModelType(pcl::SACMODEL_PLANE);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setDistanceThreshold(options.distance_threshold);
  seg.setMaxIterations(options.max_iterations);
  seg.setInputCloud(pc);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coeff;
  {
    // PCL prints a degenerate random sample (three nearly collinear points) as an error on
    // stderr; RANSAC draws another, and the result is checked below. Quiet while it runs.
    const pcl::console::VERBOSITY_LEVEL level = pcl::console::getVerbosityLevel();
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    seg.segment(inliers, coeff);
    pcl::console::setVerbosityLevel(level);
  }
  const std::size_t needed = std::max(
      options.min_inliers, static_cast<std::size_t>(std::ceil(options.min_inlier_fraction * static_cast<double>(cloud.size()))));
  if (coeff.values.size() != 4 || inliers.indices.size() < needed)
    throw CloudError(fmt::format("{}: no table plane: the best plane holds {} of {} points (need {}, band {} m)", source,
                                 inliers.indices.size(), cloud.size(), needed, options.distance_threshold));

  Eigen::Vector3d n(coeff.values[0], coeff.values[1], coeff.values[2]);
  double d = coeff.values[3];
  const double norm = n.norm();
  n /= norm;
  d /= norm;
  // In-plane basis, then the minimal rectangle of the inliers fixes origin and x axis.
  const Eigen::Vector3d a = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (a - a.dot(n) * n).normalized();
  Eigen::Vector3d e2 = n.cross(e1);
  Eigen::Vector3d origin = -d * n;
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(inliers.indices.size());
  double ss = 0.0;
  std::vector<double> off;  // |distance to the plane| per inlier
  off.reserve(inliers.indices.size());
  for (int idx : inliers.indices) {
    const Eigen::Vector3d& p = cloud[static_cast<std::size_t>(idx)];
    flat.emplace_back((p - origin).dot(e1), (p - origin).dot(e2));
    const double s = n.dot(p) + d;
    ss += s * s;
    off.push_back(std::abs(s));
  }
  Rect2 rect = min_area_rect(flat, options.extent_trim);

  // Up is the side with more points within side_band of the plane over the table's own
  // rectangle: the objects. Below the top, within its outline, the sensor sees next to
  // nothing (the top hides it), while beside the table the floor or a wall may outnumber the
  // objects. With no such point, all points within side_band vote; ties point the normal at
  // the cloud origin (the sensor, for camera-frame clouds).
  const Eigen::Vector3d along_u = rect.u.x() * e1 + rect.u.y() * e2, along_v = rect.v().x() * e1 + rect.v().y() * e2;
  const Eigen::Vector3d middle = origin + rect.center.x() * e1 + rect.center.y() * e2;
  long over = 0, all = 0;
  for (const auto& p : cloud) {
    const double s = n.dot(p) + d;
    if (std::abs(s) <= options.distance_threshold || std::abs(s) >= options.side_band) continue;
    const int side = s > 0 ? 1 : -1;
    all += side;
    const Eigen::Vector3d q = p - middle;
    if (std::abs(q.dot(along_u)) <= rect.half.x() && std::abs(q.dot(along_v)) <= rect.half.y()) over += side;
  }
  const long vote = over != 0 ? over : all;
  if (vote < 0 || (vote == 0 && d < 0)) {  // flipped: e2 turns, the in-plane y coordinates mirror
    n = -n, d = -d, e2 = -e2;
    origin = -d * n;
    rect.center.y() = -rect.center.y();
    if (rect.u.y() != 0.0) {  // the mirrored first side is the other side of the rectangle, in [0, 90 deg)
      rect.u = Eigen::Vector2d(rect.u.y(), rect.u.x());
      rect.half = Eigen::Vector2d(rect.half.y(), rect.half.x());
    }
  }
  Eigen::Matrix3d r;
  r.col(0) = rect.u.x() * e1 + rect.u.y() * e2;
  r.col(2) = n;
  r.col(1) = n.cross(r.col(0));
  TableFit fit;
  fit.table_in_cloud.t = origin + rect.center.x() * e1 + rect.center.y() * e2;
  fit.table_in_cloud.q = Eigen::Quaterniond(r).normalized();
  fit.extent = 2.0 * rect.half;
  fit.inliers = inliers.indices.size();
  fit.rms = std::sqrt(ss / static_cast<double>(inliers.indices.size()));
  const auto mid = off.begin() + static_cast<std::ptrdiff_t>(off.size() / 2);
  std::nth_element(off.begin(), mid, off.end());
  fit.noise = 1.4826 * *mid;
  return fit;
}

}  // namespace ksmc::stdlib::tabletop::perception
