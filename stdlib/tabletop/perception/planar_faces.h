// Planar faces of one cluster: per-point normals (principal axes of the neighbours within
// `normal_radius`) and region growing over neighbours whose normals agree with the
// region's, then each face extended over the free points next to it on its plane (the
// edges). A box seen by a depth sensor shows one to three faces; their normals give the
// box's orientation whether it stands upright or leans. Points at edges (high curvature)
// off every face's plane and
// small patches belong to no face.
#pragma once

#include <functional>
#include <vector>

#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/perception/point_grid.h"

namespace ksmc::stdlib::tabletop::perception {

struct FaceOptions {
  double normal_radius = 0.012;   // m, neighbourhood of a point's normal
  double grow_radius = 0.008;     // m, region-growing neighbours
  double max_angle_deg = 10.0;    // a point joins a face when its normal is this close to the face's
  double max_curvature = 0.03;    // smallest eigenvalue / trace above this: an edge point, no face
  std::size_t min_points = 30;    // smaller regions are no face
  double plane_tolerance = 0.004; // m; an edge point joins a neighbouring face this close to its plane
  // A face seen at a slant is sampled in rows farther apart than grow_radius across them
  // (dense along them): each row alone is too small a region to be a face. With row_factor
  // > 1, each face then takes the free points within row_factor x grow_radius whose normals
  // agree with it and that lie on its plane (plane_tolerance), grown from its points.
  double row_factor = 0.0;
};

struct Face {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, mean of its points' normals
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::vector<int> points;                            // indices into the cluster, ascending
};

// Faces of `points`, largest first (ties by first index: deterministic). A face's normal and
// centroid are those of the region grown by normals; the rows and edge points it takes after
// that do not move them.
std::vector<Face> planar_faces(const Points& points, const FaceOptions& options = {});

// A face cut in two by a seam of points with mixed normals (an occluder's edge, a band of
// sparse rows) is two faces. Joins the faces of `faces` (of `points`) for which `may_join`
// holds, two by two, when their normals agree (max_angle_deg), each lies on the other's plane
// (plane_tolerance, at their centroids) and they come within max(row_factor, 1) x grow_radius
// of each other. A joined face's normal and centroid are its parts' means weighted by their
// points; the faces stay largest first.
void join_coplanar_faces(const Points& points, std::vector<Face>& faces, const FaceOptions& options,
                         const std::function<bool(const Face&)>& may_join);

}  // namespace ksmc::stdlib::tabletop::perception
