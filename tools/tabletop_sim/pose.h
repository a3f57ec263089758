// Rigid poses (translation + unit quaternion) and the small rotation helpers the generator needs.
#pragma once

#include <Eigen/Geometry>

#include "tools/tabletop_sim/random.h"

namespace ksmc::tools::tabletop_sim {

struct Pose {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return q * p + t; }
  Eigen::Matrix3d rotation() const { return q.toRotationMatrix(); }
  Pose inverse() const;
};

Pose operator*(const Pose& a, const Pose& b);

// Angle (radians, in [0, pi]) of the rotation taking a to b.
double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

// Quaternion with w >= 0 (q and -q are the same rotation; this picks one for output).
Eigen::Quaterniond canonical(const Eigen::Quaterniond& q);

// Rotation about the z axis.
Eigen::Quaterniond yaw_rotation(double angle);

// Random rotation: axis uniform on the sphere, angle given.
Eigen::Quaterniond rotation_about_random_axis(Rng& rng, double angle);

// Rotation whose axis lies in the xy plane (a pure tilt of the z axis by `angle`).
Eigen::Quaterniond random_tilt(Rng& rng, double angle);

// Uniform random rotation (Shoemake).
Eigen::Quaterniond uniform_rotation(Rng& rng);

// Angle (radians) between the table normal (0,0,1) and the box axis closest to it.
double tilt_from_vertical(const Eigen::Quaterniond& q);

// Index (0,1,2) of the box axis most parallel to the table normal.
int vertical_axis(const Eigen::Quaterniond& q);

}  // namespace ksmc::tools::tabletop_sim
