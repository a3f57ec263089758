// Box geometry, support geometry, camera projection: checked against hand-computed values.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "tools/tabletop_sim/camera.h"
#include "tools/tabletop_sim/relations.h"

using namespace ksmc::tools::tabletop_sim;

namespace {
Box make_box(Eigen::Vector3d size, Eigen::Vector3d t, Eigen::Quaterniond q = Eigen::Quaterniond::Identity()) {
  Box b;
  b.size = size;
  b.pose.t = t;
  b.pose.q = q;
  return b;
}
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

TEST_CASE("SAT overlap is the penetration depth of axis-aligned boxes", "[tabletop_sim][geometry]") {
  const Box a = make_box({0.2, 0.1, 0.1}, {0, 0, 0.05});
  const Box b = make_box({0.1, 0.1, 0.1}, {0.13, 0.0, 0.05});  // overlaps 2 cm along x
  CHECK(sat_overlap(a, b) == Approx(0.02).margin(1e-12));
  const Box c = make_box({0.1, 0.1, 0.1}, {0.18, 0.0, 0.05});  // 3 cm gap along x
  CHECK(sat_overlap(a, c) == Approx(-0.03).margin(1e-12));
  CHECK(box_distance(a, c) == Approx(0.03).margin(2e-4));
  CHECK(box_distance(a, b) == Approx(-0.02).margin(5e-4));
}

TEST_CASE("Rotated box: distance across an edge", "[tabletop_sim][geometry]") {
  // A cube rotated 45 deg about z reaches sqrt(2)*h along x.
  const double h = 0.05;
  const Box a = make_box({0.1, 0.1, 0.1}, {0, 0, 0}, yaw_rotation(45 * kDeg));
  const Box b = make_box({0.1, 0.1, 0.1}, {std::sqrt(2.0) * h + h + 0.01, 0, 0});
  CHECK(box_distance(a, b) == Approx(0.01).margin(2e-4));
}

TEST_CASE("Lowest and highest point of a tilted box", "[tabletop_sim][geometry]") {
  const Box b = make_box({0.2, 0.1, 0.1}, {0, 0, 0.5}, Eigen::Quaterniond(Eigen::AngleAxisd(90 * kDeg, Eigen::Vector3d::UnitY())));
  CHECK(lowest_z(b) == Approx(0.4));
  CHECK(highest_z(b) == Approx(0.6));
  CHECK(vertical_axis(b.pose.q) == 0);
  CHECK(tilt_from_vertical(b.pose.q) == Approx(0.0).margin(1e-9));
  Rng rng(3);
  const Box t = make_box({0.1, 0.1, 0.1}, {0, 0, 0}, random_tilt(rng, 12 * kDeg));
  CHECK(tilt_from_vertical(t.pose.q) == Approx(12 * kDeg).margin(1e-9));
}

TEST_CASE("Support geometry: resting, overhanging, floating", "[tabletop_sim][geometry]") {
  const Box lower = make_box({0.2, 0.2, 0.1}, {0, 0, 0.05});
  const Box on = make_box({0.1, 0.1, 0.05}, {0.0, 0.0, 0.125});
  auto g = support_geometry(on, lower);
  CHECK(g.gap == Approx(0.0).margin(1e-12));
  CHECK(g.area == Approx(0.01).margin(1e-9));
  const Box overhang = make_box({0.1, 0.1, 0.05}, {0.125, 0.0, 0.125});  // 2.5 cm of it over the top face
  g = support_geometry(overhang, lower);
  CHECK(g.area == Approx(0.025 * 0.1).margin(1e-9));
  const Box above = make_box({0.1, 0.1, 0.05}, {0.0, 0.0, 0.145});
  CHECK(support_geometry(above, lower).gap == Approx(0.02).margin(1e-12));

  std::vector<Box> boxes{lower, on};
  const Relations rel = compute_relations(boxes, RelationParams{});
  REQUIRE(rel.support.size() == 2);
  CHECK(rel.support[0] == std::pair(0, kTableIndex));
  CHECK(rel.support[1] == std::pair(1, 0));
  CHECK(rel.contact.empty());

  // Tilted box leaning on the cube: contact, not support.
  std::vector<Box> lean{lower, make_box({0.02, 0.1, 0.2}, {0.0, 0.0, 0.0}, Eigen::Quaterniond(Eigen::AngleAxisd(-20 * kDeg, Eigen::Vector3d::UnitY())))};
  lean[1].pose.t.z() -= lowest_z(lean[1]);  // on the table
  // Slide it along +x until it touches the cube.
  double lo = 0.0, hi = 0.5;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    lean[1].pose.t.x() = mid;
    (sat_overlap(lean[0], lean[1]) > 0 ? lo : hi) = mid;
  }
  lean[1].pose.t.x() = hi + 0.0005;
  const Relations rl = compute_relations(lean, RelationParams{});
  CHECK(!rl.stable[1]);
  CHECK(rl.contact == std::vector<std::pair<int, int>>{{0, 1}, {1, kTableIndex}});
  CHECK(rl.support == std::vector<std::pair<int, int>>{{0, kTableIndex}});
}

TEST_CASE("Segment against box", "[tabletop_sim][geometry]") {
  const Box b = make_box({0.1, 0.1, 0.1}, {0, 0, 0});
  CHECK(segment_hits_box({-1, 0, 0}, {2, 0, 0}, 1.0, b));
  CHECK(!segment_hits_box({-1, 0, 0}, {2, 0, 0}, 0.4, b));  // stops before the box
  CHECK(!segment_hits_box({-1, 0.2, 0}, {2, 0, 0}, 1.0, b));
}

TEST_CASE("Camera looks at the table from above and projects the target near the centre", "[tabletop_sim][camera]") {
  Rng rng(11);
  const Camera cam;
  for (int i = 0; i < 50; ++i) {
    const CameraPlacement place;
    const Pose pose = draw_camera_pose(rng, place);
    const double dist = pose.t.norm();
    CHECK(dist > place.min_distance - 0.05);
    CHECK(dist < place.max_distance + 0.05);
    const Eigen::Vector3d forward = pose.q * Eigen::Vector3d::UnitZ();
    const double elevation = std::asin(-forward.z());
    CHECK(elevation >= place.min_elevation - 1e-9);
    CHECK(elevation <= place.max_elevation + 1e-9);
    const auto uv = project(cam, pose, Eigen::Vector3d::Zero());
    REQUIRE(uv);
    CHECK(std::abs(uv->x() - cam.cx) < 40);
    CHECK(std::abs(uv->y() - cam.cy) < 40);
    // Image y points down: a point above the table origin appears higher in the image.
    const auto up = project(cam, pose, Eigen::Vector3d(0, 0, 0.1));
    REQUIRE(up);
    CHECK(up->y() < uv->y());
  }
}

TEST_CASE("Keypoints lie on camera-facing faces and reproject", "[tabletop_sim][camera]") {
  Rng rng(5);
  const Camera cam;
  CameraPlacement place;
  const Pose camera_pose = draw_camera_pose(rng, place);
  const Box b = make_box({0.2, 0.07, 0.3}, {0, 0, 0.15}, yaw_rotation(0.3));
  KeypointParams kp;
  kp.pixel_sigma = 0.0;
  kp.outlier_rate = 0.0;
  const auto obs = sample_keypoints(rng, cam, camera_pose, b, {}, kp);
  REQUIRE(obs);
  REQUIRE(obs->model.size() == obs->image.size());
  CHECK(obs->model.size() >= 10);
  CHECK(obs->model.size() <= 30);
  for (std::size_t i = 0; i < obs->model.size(); ++i) {
    const auto uv = project(cam, camera_pose, b.pose.apply(obs->model[i]));
    REQUIRE(uv);
    CHECK((*uv - obs->image[i]).norm() < 1e-9);
    // On the surface: one coordinate at +-half size.
    const Eigen::Vector3d rel = obs->model[i].cwiseAbs() - 0.5 * b.size;
    CHECK(rel.maxCoeff() == Approx(0.0).margin(1e-12));
    // Facing the camera.
    int axis = 0;
    rel.maxCoeff(&axis);
    const Eigen::Vector3d normal = b.pose.q * (Eigen::Vector3d::Unit(axis) * (obs->model[i][axis] > 0 ? 1.0 : -1.0));
    CHECK(normal.dot(camera_pose.t - b.pose.apply(obs->model[i])) > 0.0);
  }
  // A box entirely hidden behind a larger one sees no keypoints.
  const Box wall = make_box({0.3, 0.3, 0.3}, b.pose.t + 0.5 * (camera_pose.t - b.pose.t));
  std::vector<Box> occluders{wall};
  CHECK(!sample_keypoints(rng, cam, camera_pose, b, occluders, kp));
}
