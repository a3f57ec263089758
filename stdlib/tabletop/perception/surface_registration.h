// Refines a rigid transform from cloud points to a set of boxes (ICP against the box
// surfaces): each point is paired with the closest surface point of its nearest box,
// pairs farther than `max_distance` are dropped, and Umeyama re-fits the transform.
// Used to relate the HOPE cloud to its annotated boxes more precisely than the box
// centres can (the detected centres are biased by the partial views).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/perception/truth_eval.h"

namespace ksmc::stdlib::tabletop::perception {

struct SurfaceFit {
  Eigen::Isometry3d points_to_boxes = Eigen::Isometry3d::Identity();
  double rms = 0.0;       // point-to-surface distance over the kept pairs [m]
  std::size_t kept = 0;   // pairs within max_distance at the end
};

// Closest point of the box's surface (faces) to p; p may lie inside.
Eigen::Vector3d closest_surface_point(const TruthBox& box, const Eigen::Vector3d& p);

// Index of the box whose surface is nearest to p (and within max_distance), or -1.
int nearest_box(const std::vector<TruthBox>& boxes, const Eigen::Vector3d& p, double max_distance);

// Matches clusters (points in the boxes' frame) to boxes by their points: a box takes the
// cluster holding most of its points; a cluster goes to at most one box. Returns a
// Registration carrying `transform` whose match is per cluster (-1: no box).
Registration match_by_points(const std::vector<Points>& clusters, const std::vector<TruthBox>& boxes,
                             const Eigen::Isometry3d& transform, double max_distance);

SurfaceFit fit_to_box_surfaces(const Points& points, const std::vector<TruthBox>& boxes, const Eigen::Isometry3d& initial,
                               double max_distance, int iterations = 30);

}  // namespace ksmc::stdlib::tabletop::perception
