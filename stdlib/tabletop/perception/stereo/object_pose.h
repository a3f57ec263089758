// Poses of database objects from stereo-consistent keypoints (Alg. 2 lines 2-10):
// * both descriptors of a stereo point (left and right) are matched to the object's model
//   (ratio test); the point is valid for the object when both pick the same model point
//   (seed Fig. 4.13);
// * pose hypotheses from random triples of valid 3D-3D matches (Umeyama, no scale; a
//   triple whose side lengths differ between scene and model by more than
//   `triple_tolerance` is not rigid and is skipped);
// * the hypotheses are clustered (translation and rotation distance); the biggest cluster
//   wins, its best hypothesis (most inliers) is the RANSAC consensus; the pose is refined by
//   Umeyama on the inliers until the inlier set is stable;
// * the object is detected when at least `min_inliers` agree, or `min_verified_inliers`
//   that fit within `verified_rms` with `verified_cluster` hypotheses behind them; its
//   inliers are the keypoints recorded for the reprojection likelihood (left pixel +
//   model point).
// Several instances of one database object (two copies of a product): once an instance is
// found, the matches its pose explains are set aside and the search runs again on the rest,
// up to `max_instances`; an instance whose centre lies within 0.9 x the object's smallest
// side of one already found is the same box and ends the search (two boxes cannot overlap).
// Deterministic: seeded per object and instance.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "stdlib/tabletop/perception/stereo/object_db.h"
#include "stdlib/tabletop/perception/stereo/stereo_points.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct PoseOptions {
  double ratio = 0.8;               // database descriptor ratio test
  int hypotheses = 300;             // random triples per object
  double triple_tolerance = 0.01;   // m
  double min_triple_side = 0.01;    // m, shortest model side of a usable triple
  double inlier_tolerance = 0.01;   // m, |T model - scene| of a hypothesis' inliers
  double refine_tolerance = 0.006;  // m, the inlier gate while refining the final pose
  double cluster_translation = 0.02;  // m
  double cluster_angle = 0.1745;      // rad (10 deg)
  int min_matches = 5;
  int min_inliers = 6;
  // Fewer inliers, down to this many, still detect the object when they fit its pose
  // tightly (rms) and the winning cluster holds several hypotheses: partly hidden boxes.
  int min_verified_inliers = 5;
  double verified_rms = 0.0015;       // m
  int verified_cluster = 3;           // hypotheses
  int max_instances = 4;              // per database object
  std::uint64_t seed = 1;
};

struct ObjectDetection {
  int object = -1;                       // index into the database
  int instance = 0;                      // 0 for the first copy of the object found, 1, 2, ... then
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // object frame -> left camera
  int matches = 0;                       // valid 3D-3D matches
  int hypotheses = 0;                    // rigid triples tried
  int clusters = 0;
  int cluster_size = 0;                  // hypotheses in the winning cluster
  std::vector<int> inliers;              // indices into the stereo points
  std::vector<Eigen::Vector3d> model;    // model point of each inlier
  double rms = 0.0;                      // m, inlier residual
};

struct Match3d {
  int point = -1;   // stereo point index
  int model = -1;   // model point index
};

// The valid matches of the stereo points to one object model.
std::vector<Match3d> match_to_model(const StereoPoints& points, const ObjectModel& model, double ratio);

// Estimates the object's pose from its matches; nullopt-like: `inliers` empty when not found.
ObjectDetection estimate_pose(const StereoPoints& points, const ObjectModel& model, const std::vector<Match3d>& matches,
                              const PoseOptions& options, std::uint64_t seed);

// All database objects found (database order; the instances of one object in the order found).
std::vector<ObjectDetection> detect_objects(const StereoPoints& points, const std::vector<ObjectModel>& db,
                                            const PoseOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception::stereo
