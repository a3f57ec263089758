// The simulator's scorer (tools/perception/visibility.h): what a view shows of each box.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "stdlib/tabletop/camera_geometry.h"
#include "tools/perception/visibility.h"

namespace ts = ksmc::tools::tabletop_sim;
using ksmc::tools::perception::box_views;

namespace {

// A camera at `eye` (table frame) looking at `target`, OpenCV axes (x right, y down, z forward).
ts::Pose looking_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  ts::Pose p;
  p.t = eye;
  p.q = ksmc::stdlib::tabletop::look_along(target - eye);
  return p;
}

// An upright box of `size` with its bottom at height `bottom`, centred at (x, y), turned by `yaw`.
ts::Box upright(double x, double y, double bottom, const Eigen::Vector3d& size, double yaw = 0.0) {
  ts::Box b;
  b.size = size;
  b.pose.t = Eigen::Vector3d(x, y, bottom + 0.5 * size.z());
  b.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return b;
}

const ts::Camera kCamera;
const ts::Pose kView = looking_at(Eigen::Vector3d(0.3, -0.7, 0.6), Eigen::Vector3d(0.0, 0.0, 0.05));

// The viewing direction on the table, from the camera towards the origin.
const Eigen::Vector3d kAlong = Eigen::Vector3d(-0.3, 0.7, 0.0).normalized();
const double kYaw = std::atan2(kAlong.y(), kAlong.x());

}  // namespace

TEST_CASE("visibility: a box in full view on the table shows all its extents", "[perception][sim]") {
  const std::vector<ts::Box> boxes{upright(0.0, 0.0, 0.0, {0.2, 0.1, 0.08}, 0.4)};
  const auto v = box_views(kCamera, kView, boxes, 2);
  REQUIRE(v.size() == 1);
  CHECK(v[0].visible == Approx(1.0).margin(1e-9));
  CHECK(v[0].extents_shown);
}

TEST_CASE("visibility: a box on the table whose foot is hidden shows its height, one on a hidden box does not",
          "[perception][sim]") {
  // A 20 cm tall box, and 3 cm in front of it a 12 cm box that hides the lower part of its face.
  const Eigen::Vector3d front = -0.11 * kAlong;
  const ts::Box hider = upright(front.x(), front.y(), 0.0, {0.06, 0.2, 0.12}, kYaw);
  const std::vector<ts::Box> standing{upright(0.0, 0.0, 0.0, {0.1, 0.1, 0.2}, kYaw), hider};
  const auto v = box_views(kCamera, kView, standing, 2);
  REQUIRE(v.size() == 2);
  CHECK(v[0].visible < 0.9);
  CHECK(v[0].extents_shown);  // the table is its bottom
  // The same box lifted 5 cm (on something the front box hides): its bottom is not seen.
  const std::vector<ts::Box> lifted{upright(0.0, 0.0, 0.05, {0.1, 0.1, 0.2}, kYaw), hider};
  CHECK_FALSE(box_views(kCamera, kView, lifted, 2)[0].extents_shown);
}

TEST_CASE("visibility: a long box whose far end is behind a tall box does not show its length", "[perception][sim]") {
  // A low 30 cm box along the viewing direction.
  const ts::Box low = upright(0.0, 0.0, 0.0, {0.3, 0.06, 0.04}, kYaw);
  const std::vector<ts::Box> alone{low};
  const auto seen_alone = box_views(kCamera, kView, alone, 2);
  CHECK(seen_alone[0].extents_shown);
  // A tall box stands across it, 6 cm in front of its centre, hiding what lies behind.
  const Eigen::Vector3d front = -0.06 * kAlong;
  const std::vector<ts::Box> both{low, upright(front.x(), front.y(), 0.0, {0.05, 0.25, 0.3}, kYaw)};
  const auto v = box_views(kCamera, kView, both, 2);
  REQUIRE(v.size() == 2);
  CHECK(v[0].visible < 0.9);
  CHECK_FALSE(v[0].extents_shown);
  CHECK(v[1].extents_shown);
}

TEST_CASE("visibility: a box seen as two ends either side of an occluder is not shown whole", "[perception][sim]") {
  // A low 30 cm box across the view, and a thin post in front of its middle.
  const ts::Box low = upright(0.0, 0.0, 0.0, {0.3, 0.06, 0.04}, kYaw + 0.5 * 3.14159265358979323846);
  const std::vector<ts::Box> alone{low};
  CHECK(box_views(kCamera, kView, alone, 2)[0].extents_shown);
  const Eigen::Vector3d front = -0.1 * kAlong;
  const std::vector<ts::Box> both{low, upright(front.x(), front.y(), 0.0, {0.04, 0.04, 0.3}, kYaw)};
  const auto v = box_views(kCamera, kView, both, 2);
  CHECK(v[0].visible > 0.5);  // most of it is in view ...
  CHECK_FALSE(v[0].extents_shown);  // ... in two pieces, neither as long as the box
}

TEST_CASE("visibility: a box outside the image is neither visible nor shown", "[perception][sim]") {
  const std::vector<ts::Box> boxes{upright(3.0, 3.0, 0.0, {0.1, 0.1, 0.1})};
  const auto v = box_views(kCamera, kView, boxes, 2);
  CHECK(v[0].visible == 0.0);
  CHECK_FALSE(v[0].extents_shown);
}
