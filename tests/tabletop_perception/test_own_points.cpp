// own_points: the points each box of a cluster owns (the cloud likelihood's observations).
#include <catch2/catch.hpp>

#include <vector>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/perception/own_points.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::Obb;

namespace {

UprightBox upright(double cx, double cy, double bottom, const Eigen::Vector3d& size) {
  UprightBox b;
  b.pose.t = Eigen::Vector3d(cx, cy, bottom + 0.5 * size.z());
  b.size = size;
  return b;
}

}  // namespace

TEST_CASE("own points: the layers of a stack stay apart, noise within the margin stays", "[perception][own_points]") {
  // A bottle split into its body (8 x 8 x 15 cm) and its cap (3 x 3 x 3 cm) on it; its
  // shoulders rise 8 mm above the body's box beside the cap. Noise: a body side point 6 mm
  // outside the body, a cap point 2 mm above the body's top, a body top point 2 mm under the
  // cap's bottom; one 5 mm under it is the body's only.
  const std::vector<UprightBox> boxes = {upright(0, 0, 0, {0.08, 0.08, 0.15}), upright(0, 0, 0.15, {0.03, 0.03, 0.03}),
                                         upright(0.5, 0, 0, {0.05, 0.05, 0.05})};
  const std::vector<std::size_t> cluster_of = {0, 0, 1};
  const Points cluster = {
      {0.04, 0.0, 0.07},    // body side
      {0.046, 0.0, 0.07},   // body side, 6 mm out
      {0.03, 0.03, 0.158},  // shoulder, 8 mm above the body, beside the cap
      {0.0, 0.0, 0.152},    // cap bottom region, 2 mm above the body's top
      {0.01, 0.0, 0.18},    // cap top
      {0.0, 0.01, 0.148},   // body top, 2 mm under the cap
      {0.0, -0.01, 0.145},  // body top, 5 mm under the cap
  };
  OwnPointsOptions options;
  options.layer_margin = 0.003;
  const Points body = own_points(boxes, cluster_of, 0, cluster, options);
  const Points cap = own_points(boxes, cluster_of, 1, cluster, options);
  // The body: its sides (one 6 mm out, within the 1 cm margin), its top, and the point 2 mm
  // above its top (within the layer margin); not the shoulder 8 mm up, nor the cap's top.
  CHECK(body.size() == 5);
  for (const auto& p : body) CHECK(p.z() <= 0.153);
  // The cap: its own two points and the one 2 mm under its bottom, not the one 5 mm under.
  REQUIRE(cap.size() == 3);
  for (const auto& p : cap) CHECK(p.z() >= 0.1475);
  // With the layers ignored (a 1 m layer margin) the shoulder is the body's again: it lies
  // within 1 cm of the body's box.
  options.layer_margin = 1.0;
  CHECK(own_points(boxes, cluster_of, 0, cluster, options).size() == 6);
  // A box alone in its cluster owns all of it.
  CHECK(own_points(boxes, cluster_of, 2, cluster, options).size() == cluster.size());
}

TEST_CASE("own points: a box lying across a strip of another keeps its rim from the strip", "[perception][own_points]") {
  // The front end found only the front 27 mm of a lower box (its visible side and top edge);
  // the box lying on it is 12 cm deep, its centre behind the strip. The upper box's front face
  // starts at the strip's top: points 4 and 8 mm above it are the upper box's, not the strip's
  // (they would pull the strip up in the cloud likelihood).
  const std::vector<UprightBox> boxes = {upright(0, 0, 0, {0.24, 0.027, 0.097}),
                                         upright(0, 0.045, 0.097, {0.22, 0.116, 0.095})};
  const std::vector<std::size_t> cluster_of = {0, 0};
  const Points cluster = {
      {0.05, -0.0135, 0.05},   // the strip's front face
      {0.05, 0.0, 0.097},      // its top edge
      {0.05, -0.013, 0.101},   // the upper box's front face, 4 mm up
      {0.05, -0.013, 0.105},   // and 8 mm up
      {0.05, -0.013, 0.15},    // and well up
  };
  OwnPointsOptions options;
  options.layer_margin = 0.003;
  const Points strip = own_points(boxes, cluster_of, 0, cluster, options);
  REQUIRE(strip.size() == 2);
  for (const auto& p : strip) CHECK(p.z() <= 0.1);
  CHECK(own_points(boxes, cluster_of, 1, cluster, options).size() == 4);
  // Beside it, not over it (the footprints 1 cm apart): the neighbour's points stay the
  // strip's where they are within its margin.
  const std::vector<UprightBox> apart = {boxes[0], upright(0, 0.0835, 0.097, {0.22, 0.116, 0.095})};
  CHECK(own_points(apart, cluster_of, 0, cluster, options).size() == 4);
}

TEST_CASE("own points: for the likelihood, a point nearer another box is that box's", "[perception][own_points]") {
  // A box propped against a lower box's top front edge (tilted 30 degrees about x, its back face
  // on that edge): points on its face just above the lower box's top lie within 1 cm of
  // the lower box, and pulled it up in the cloud likelihood.
  UprightBox leaning;
  leaning.size = Eigen::Vector3d(0.10, 0.03, 0.12);
  leaning.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5236, Eigen::Vector3d::UnitX()));
  leaning.pose.t = Eigen::Vector3d(0.0, -0.058, 0.0615);
  const std::vector<UprightBox> boxes = {upright(0, 0, 0, {0.10, 0.06, 0.08}), leaning};
  const std::vector<std::size_t> cluster_of = {0, 0};
  const Obb lean = Obb::from_pose(leaning.pose, leaning.size);
  Points cluster = {{0.0, -0.03, 0.04}, {0.0, 0.0, 0.08}};  // the lower box's front face and top
  // The leaning box's back face (local y = +half), along its length: some of it is within 1 cm
  // of the lower box.
  for (double s = -0.06; s <= 0.06; s += 0.005)
    cluster.push_back(lean.center + lean.axes.col(1) * lean.half.y() + lean.axes.col(2) * s);
  const Obb lower = Obb::from_pose(boxes[0].pose, boxes[0].size);
  std::size_t near_lower = 0;
  for (std::size_t k = 2; k < cluster.size(); ++k) near_lower += lower.contains(cluster[k], 0.01);
  REQUIRE(near_lower >= 3);
  OwnPointsOptions options;
  options.layer_margin = 0.003;
  CHECK(own_points(boxes, cluster_of, 0, cluster, options).size() == 2 + near_lower);
  options.nearest = true;
  const Points mine = own_points(boxes, cluster_of, 0, cluster, options);
  for (const auto& p : mine) CHECK(lower.distance_to(p) <= lean.distance_to(p) + options.layer_margin);
  CHECK(mine.size() < 2 + near_lower);
  CHECK(mine.size() >= 2);  // its own face and top stay
  CHECK(own_points(boxes, cluster_of, 1, cluster, options).size() == cluster.size() - 2);
}

TEST_CASE("own points: for the likelihood, what is seen under a box is not its own", "[perception][own_points]") {
  // A book (25 x 13 x 4 cm) lying on a longer one the front end made no box of: the lower
  // book's rim shows 1.7 cm beyond each end, 3 cm above the table, and its side below the upper
  // book's bottom. The side's points pulled the upper book into a tilt in the cloud likelihood. One cluster, one box: the upper book's.
  const std::vector<UprightBox> boxes = {upright(0, 0, 0.03, {0.25, 0.13, 0.04})};
  const std::vector<std::size_t> cluster_of = {0};
  Points cluster;
  for (double x = -0.12; x <= 0.12; x += 0.01) cluster.push_back({x, 0.0, 0.07});        // its top
  for (double x = -0.12; x <= 0.12; x += 0.02) cluster.push_back({x, -0.065, 0.0305});   // its side, at its bottom edge
  std::size_t under = 0;
  for (double x = -0.14; x <= 0.14; x += 0.02, ++under) cluster.push_back({x, -0.068, 0.015});  // the lower book's side
  cluster.push_back({0.135, 0.0, 0.0295});  // the lower book's rim beyond the end, level with its bottom: kept
  OwnPointsOptions options;
  options.layer_margin = 0.0015;  // 3 x 0.5 mm depth noise
  // The front end's passes read the whole cluster; the likelihood's points end at its bottom.
  CHECK(own_points(boxes, cluster_of, 0, cluster, options).size() == cluster.size());
  options.nearest = true;
  CHECK(own_points(boxes, cluster_of, 0, cluster, options).size() == cluster.size());
  options.not_below = true;
  const Points mine = own_points(boxes, cluster_of, 0, cluster, options);
  CHECK(mine.size() == cluster.size() - under);
  for (const auto& p : mine) CHECK(p.z() >= 0.03 - options.layer_margin);
  // The same with a second box in the cluster (a box beside it): the bottom still holds.
  const std::vector<UprightBox> two = {boxes[0], upright(0.5, 0, 0, {0.05, 0.05, 0.05})};
  CHECK(own_points(two, {0, 0}, 0, cluster, options).size() == cluster.size() - under);
}
