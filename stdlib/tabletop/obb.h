// Oriented bounding box in the table frame (z = table normal, table top at z = 0).
#pragma once

#include <array>

#include <Eigen/Core>

#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop {

struct Obb {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: unit box axes in the table frame
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5);  // half extents along the axes (> 0)

  // Builds the box of full extents `size` centred at pose.t with orientation pose.q.
  static Obb from_pose(const Pose& pose, const Eigen::Vector3d& size);

  // Vertex k (k in 0..7): bit i of k selects the sign along axis i.
  [[nodiscard]] Eigen::Vector3d vertex(int k) const;
  [[nodiscard]] std::array<Eigen::Vector3d, 8> vertices() const;
  // Edge k (k in 0..11) as its two end points.
  [[nodiscard]] std::array<Eigen::Vector3d, 2> edge(int k) const;

  // Lowest / highest z over the eight vertices, and the vertical extent.
  [[nodiscard]] double min_z() const;
  [[nodiscard]] double max_z() const;
  [[nodiscard]] double vertical_extent() const { return max_z() - min_z(); }

  // Closest point of the (solid) box to p, and the distance (0 inside).
  [[nodiscard]] Eigen::Vector3d closest_point(const Eigen::Vector3d& p) const;
  [[nodiscard]] double distance_to(const Eigen::Vector3d& p) const;
  // True when p lies inside the box or within `slack` of its surface.
  [[nodiscard]] bool contains(const Eigen::Vector3d& p, double slack = 0.0) const;
};

}  // namespace ksmc::stdlib::tabletop
