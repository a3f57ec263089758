// Rigid 6D pose (translation + unit quaternion) used for objects, the table and the camera.
#pragma once

#include <Eigen/Geometry>

namespace ksmc::stdlib::tabletop {

struct Pose {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  // unit quaternion

  [[nodiscard]] Eigen::Isometry3d isometry() const {
    Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
    iso.linear() = q.toRotationMatrix();
    iso.translation() = t;
    return iso;
  }
  [[nodiscard]] Eigen::Matrix3d rotation() const { return q.toRotationMatrix(); }

  static Pose from_isometry(const Eigen::Isometry3d& iso) {
    Pose p;
    p.t = iso.translation();
    p.q = Eigen::Quaterniond(iso.rotation());
    p.q.normalize();
    return p;
  }
  // this ∘ other: maps points of other's child frame into this pose's parent frame.
  [[nodiscard]] Pose compose(const Pose& other) const {
    Pose p;
    p.q = (q * other.q).normalized();
    p.t = q * other.t + t;
    return p;
  }
  [[nodiscard]] Pose inverse() const {
    Pose p;
    p.q = q.conjugate();
    p.t = -(p.q * t);
    return p;
  }
};

}  // namespace ksmc::stdlib::tabletop
