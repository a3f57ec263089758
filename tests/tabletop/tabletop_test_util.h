// Small builders shared by the table-top tests.
#pragma once

#include <string>

#include <Eigen/Geometry>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::tests::tabletop {

namespace tt = ksmc::stdlib::tabletop;

inline tt::Obb box(const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                   const Eigen::Matrix3d& rot = Eigen::Matrix3d::Identity()) {
  tt::Obb b;
  b.center = center;
  b.axes = rot;
  b.half = 0.5 * size;
  return b;
}

inline Eigen::Matrix3d rot(double angle_deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle_deg * 3.14159265358979323846 / 180.0, axis.normalized()).toRotationMatrix();
}

inline tt::SceneObject object(const std::string& id, const Eigen::Vector3d& center, const Eigen::Vector3d& size,
                              const Eigen::Matrix3d& r = Eigen::Matrix3d::Identity()) {
  tt::SceneObject o;
  o.id = id;
  o.model = "box";
  o.size = size;
  o.pose.t = center;
  o.pose.q = Eigen::Quaterniond(r);
  return o;
}

}  // namespace ksmc::tests::tabletop
