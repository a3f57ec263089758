// blocks: a box across the lines of sight of another object's keypoints
// (extract_blocks.h, blocks::obb::blocks; the evidence of domains/tabletop.ksm's r28, r29);
// hides: a box in front of the part of another estimate's surface that would show keypoints
// (extract_hides.h, blocks::obb::hides; r30).
#include <catch2/catch.hpp>

#include <vector>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/extract_blocks.h"
#include "stdlib/tabletop/extract_hides.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using Eigen::Vector3d;

namespace {

constexpr double kMargin = 0.006;

// A 10 cm cube standing on the table at (x, y) with `n` keypoints spread over its face towards
// the camera (-x), and the camera 1 m away along -x at the cube's mid height.
SceneObject seen_cube(const char* id, double x, double y, int n) {
  SceneObject o = object(id, Vector3d(x, y, 0.05), Vector3d(0.1, 0.1, 0.1));
  for (int i = 0; i < n; ++i) {
    const double u = -0.04 + 0.08 * (i % 5) / 4.0, v = -0.04 + 0.08 * (i / 5 % 5) / 4.0;
    o.keypoints_model.emplace_back(-0.05, u, v);
    o.keypoints_image.emplace_back(0.0, 0.0);
  }
  return o;
}

const Vector3d kCamera(-1.0, 0.0, 0.05);

Obb box_at(const Vector3d& centre, const Vector3d& size) {
  Pose p;
  p.t = centre;
  return Obb::from_pose(p, size);
}

}  // namespace

TEST_CASE("blocks: a box between the camera and a box's keypoints hides them", "[geometry]") {
  const SceneObject seen = seen_cube("seen", 0.0, 0.0, 25);
  // A floating 8 cm box half way to the camera, in front of the whole face.
  CHECK(keypoints_behind(box_at({-0.5, 0.0, 0.05}, {0.08, 0.2, 0.2}), seen.pose, seen.keypoints_model, kCamera,
                         kMargin) == 25);
  // The same box 30 cm to the side: no line of sight crosses it.
  CHECK(keypoints_behind(box_at({-0.5, 0.3, 0.05}, {0.08, 0.2, 0.2}), seen.pose, seen.keypoints_model, kCamera,
                         kMargin) == 0);
  // Thinner than twice the margin along the line of sight: pose noise could put it anywhere.
  CHECK(keypoints_behind(box_at({-0.5, 0.0, 0.05}, {0.01, 0.2, 0.2}), seen.pose, seen.keypoints_model, kCamera,
                         kMargin) == 0);
}

TEST_CASE("blocks: a box covering the seen face hides it; one cutting the edge of the view by pose noise does not",
          "[geometry]") {
  const SceneObject seen = seen_cube("seen", 0.0, 0.0, 25);
  // A box standing against the seen face, in front of it: the face cannot be seen.
  CHECK(keypoints_behind(box_at({-0.1, 0.0, 0.05}, {0.1, 0.2, 0.2}), seen.pose, seen.keypoints_model, kCamera,
                         kMargin) == 25);
  // A copy shifted 3 cm towards the camera: its core covers the seen face.
  CHECK(keypoints_behind(box_at({-0.03, 0.0, 0.05}, {0.1, 0.1, 0.1}), seen.pose, seen.keypoints_model, kCamera,
                         kMargin) == 25);
  // A neighbour beside the face whose side reaches 5 mm across the lines of sight of the
  // outermost row (y = 0.04): that row only without the margin.
  const Obb beside = box_at({-0.07, 0.085, 0.05}, {0.1, 0.1, 0.1});
  CHECK(keypoints_behind(beside, seen.pose, seen.keypoints_model, kCamera, 0.0) == 5);
  CHECK(keypoints_behind(beside, seen.pose, seen.keypoints_model, kCamera, kMargin) == 0);
}

TEST_CASE("blocks: the evidence needs min_keypoints and min_fraction of the keypoints", "[geometry]") {
  const SceneObject seen = seen_cube("seen", 0.0, 0.0, 25);
  // A narrow post in front of the face's first row of keypoints (u = -0.04): 5 of 25.
  const Obb post = box_at({-0.5, -0.04 * 0.5, 0.05}, {0.05, 0.02, 0.2});
  const int hidden = keypoints_behind(post, seen.pose, seen.keypoints_model, kCamera, kMargin);
  REQUIRE(hidden == 5);
  CHECK(extract_blocks(post, seen.pose, seen.keypoints_model, kCamera, kMargin, 3, 0.1));
  CHECK_FALSE(extract_blocks(post, seen.pose, seen.keypoints_model, kCamera, kMargin, 6, 0.1));
  CHECK_FALSE(extract_blocks(post, seen.pose, seen.keypoints_model, kCamera, kMargin, 3, 0.25));
  CHECK_FALSE(extract_blocks(post, seen.pose, {}, kCamera, kMargin, 1, 0.0));  // no keypoints
}

TEST_CASE("blocks: the block reads the camera from the scene and the keypoints of the second body", "[geometry]") {
  Scene input;
  input.table_in_camera.t = -kCamera;  // the camera at kCamera in the table frame, axes aligned
  input.objects.push_back(seen_cube("seen", 0.0, 0.0, 25));
  input.objects.push_back(object("front", Vector3d(-0.5, 0.0, 0.05), Vector3d(0.08, 0.2, 0.2)));
  const blocks::Scene s(input);
  CHECK(blocks::obb::blocks(s, s.se3(2), s.vec3(2), s.se3(1), s.vec3(1), kMargin, 3, 0.1));
  CHECK_FALSE(blocks::obb::blocks(s, s.se3(1), s.vec3(1), s.se3(2), s.vec3(2), kMargin, 3, 0.1));  // no keypoints
  CHECK_FALSE(blocks::obb::blocks(s, s.se3(0), s.vec3(0), s.se3(1), s.vec3(1), kMargin, 3, 0.1));  // the table
  CHECK_FALSE(blocks::obb::blocks(s, s.se3(1), s.vec3(1), s.se3(1), s.vec3(1), kMargin, 3, 0.1));  // itself
}

TEST_CASE("hides: the share of the camera-facing surface behind a box's core", "[geometry]") {
  // From kCamera (mid height, along -x) only the seen cube's -x face faces the camera.
  const Obb seen = box_at({0.0, 0.0, 0.05}, {0.1, 0.1, 0.1});
  CHECK(covered_share(box_at({-0.5, 0.0, 0.05}, {0.08, 0.3, 0.3}), seen, kCamera, kMargin) == Approx(1.0));
  CHECK(covered_share(box_at({-0.5, 0.5, 0.05}, {0.08, 0.3, 0.3}), seen, kCamera, kMargin) == 0.0);
  // A box covering y < 0 at x = -0.5: the lines of sight to the face (x = -0.05) cross its core
  // (y <= -0.006) where y <= -0.0114 on the face: the first two of the six sample rows.
  const Obb half = box_at({-0.5, -0.1, 0.05}, {0.08, 0.2, 0.3});
  CHECK(covered_share(half, seen, kCamera, kMargin) == Approx(2.0 / 6.0));
  // 25 keypoints on the other two thirds predict 12.5 on the covered third; 5 predict 2.5.
  CHECK(extract_hides(half, seen, 25, kCamera, kMargin, 3.0));
  CHECK_FALSE(extract_hides(half, seen, 5, kCamera, kMargin, 3.0));
  CHECK_FALSE(extract_hides(half, seen, 0, kCamera, kMargin, 0.0));  // no keypoints: nothing to expect
  // Thinner than twice the margin: it covers nothing.
  CHECK(covered_share(box_at({-0.5, 0.0, 0.05}, {0.01, 0.3, 0.3}), seen, kCamera, kMargin) == 0.0);
}

TEST_CASE("hides: the block reads the camera from the scene and the keypoint count of the second body", "[geometry]") {
  Scene input;
  input.table_in_camera.t = -kCamera;
  input.objects.push_back(seen_cube("seen", 0.0, 0.0, 25));
  input.objects.push_back(object("front", Vector3d(-0.5, 0.0, 0.05), Vector3d(0.08, 0.3, 0.3)));
  const blocks::Scene s(input);
  CHECK(blocks::obb::hides(s, s.se3(2), s.vec3(2), s.se3(1), s.vec3(1), kMargin, 3.0));
  CHECK_FALSE(blocks::obb::hides(s, s.se3(1), s.vec3(1), s.se3(2), s.vec3(2), kMargin, 0.0));  // no keypoints
  CHECK_FALSE(blocks::obb::hides(s, s.se3(0), s.vec3(0), s.se3(1), s.vec3(1), kMargin, 3.0));  // the table
  CHECK_FALSE(blocks::obb::hides(s, s.se3(1), s.vec3(1), s.se3(1), s.vec3(1), kMargin, 3.0));  // itself
}
