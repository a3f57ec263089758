// Oriented boxes for the independent scene generator (tools/tabletop_indep): its own
// geometry, written apart from tools/tabletop_sim so that the two generators share no code
// and no modelling choice. Table frame: z up, the table top is the plane z = 0.
#pragma once

#include <array>

#include <Eigen/Geometry>

namespace ksmc::tools::tabletop_indep {

struct Obb {
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // full edge lengths, m
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();

  Eigen::Vector3d half() const { return 0.5 * size; }
  std::array<Eigen::Vector3d, 8> corners() const;
  double bottom() const;  // lowest z
  double top() const;     // highest z
  // The box axis closest to vertical, and whether it points up.
  int up_axis() const;
  double tilt() const;  // rad between up_axis and z
};

// Penetration depth along the separating axis of least overlap (15 SAT axes); negative is the
// clearance along the best separating axis (a lower bound of the distance, exact for faces).
double penetration(const Obb& a, const Obb& b);

// Rotation about z by `yaw` composed with the box resting on face `axis` (its `axis`-th
// column is +z, or -z when `flip`).
Eigen::Matrix3d resting_rotation(int axis, bool flip, double yaw);

// Area of the part of `upper`'s footprint (a level box) that lies over `lower`'s top face,
// sampled on a grid (both boxes level).
double footprint_overlap(const Obb& upper, const Obb& lower, int samples = 24);

// Whether the point (x, y) lies over the top rectangle of level box `b`, `margin` inside.
bool over_top(const Obb& b, const Eigen::Vector2d& p, double margin);

}  // namespace ksmc::tools::tabletop_indep
