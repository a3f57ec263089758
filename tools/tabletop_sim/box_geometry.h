// Geometry of oriented boxes (OBBs) in the table frame: vertices, overlap, distance, ray tests.
// The table is the half-space below z = 0 in this frame.
#pragma once

#include <array>

#include <Eigen/Core>

#include "tools/tabletop_sim/pose.h"

namespace ksmc::tools::tabletop_sim {

struct Box {
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // full extents, metres
  Pose pose;                                       // centre + orientation
};

std::array<Eigen::Vector3d, 8> box_vertices(const Box& b);
double lowest_z(const Box& b);
double highest_z(const Box& b);

// Separating-axis test over the 15 candidate axes. Returns the smallest overlap: > 0 is the
// exact penetration depth (minimum translation distance) of two intersecting boxes, <= 0 means
// the boxes are separated and -value is a lower bound on their distance.
double sat_overlap(const Box& a, const Box& b);

// Signed distance between two boxes from Bullet's GJK (gap > 0) and EPA (penetration < 0).
double box_distance(const Box& a, const Box& b);

// True when the segment origin + s * dir, s in [0, max_s], passes through the box interior
// (shrunk by `shrink` metres on every side so grazing rays do not count).
bool segment_hits_box(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double max_s,
                      const Box& b, double shrink = 1e-4);

// Overlap of the xy footprints of two boxes placed upright (yaw only), inflated by `clearance`.
bool footprints_overlap(const Eigen::Vector2d& ca, const Eigen::Vector2d& half_a, double yaw_a,
                        const Eigen::Vector2d& cb, const Eigen::Vector2d& half_b, double yaw_b,
                        double clearance);

}  // namespace ksmc::tools::tabletop_sim
