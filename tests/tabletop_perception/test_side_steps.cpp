// Side steps (side_steps.h): a box resting on one of about its footprint, whose top is hidden,
// is two boxes; a single box stays one, with depth noise and with its lower part half hidden
// behind a box in front (occlusion changes which faces are seen, not where they are); one face
// of a lower box under a step is not a box of its own, two faces are.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "stdlib/tabletop/perception/stack_split.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::tests::perception::CastBox;
using ksmc::tests::perception::cast_view;
using ksmc::tests::perception::upright_box;

namespace {

// A rendered view (occlusion included) with 1 mm of depth noise along the rays; the points
// above 12 mm within `reach` of (cx, cy) in x and y, as one cluster.
Points view(const std::vector<CastBox>& boxes, double cx, double cy, double reach) {
  const Eigen::Vector3d sensor(0.45, -0.55, 0.6);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.001);
  Points out;
  for (const auto& p : cast_view(sensor, Eigen::Vector3d(cx, cy, 0.05), 0.3, 0.002, boxes, 0.6, 0.4)) {
    if (p.z() <= 0.012 || std::abs(p.x() - cx) > reach || std::abs(p.y() - cy) > reach) continue;
    out.push_back(p + noise(rng) * (p - sensor).normalized());
  }
  return out;
}

double bottom_of(const UprightBox& b) { return b.pose.t.z() - 0.5 * b.size.z(); }

}  // namespace

TEST_CASE("side steps: a box resting on one of about its footprint is two boxes", "[perception][stack][sides]") {
  // A 112 x 66 x 29 mm box on a 100 x 56 x 38 mm one, turned 3 degrees and set off by 2 mm:
  // it hides the whole lower top, so there is one plateau.
  const Points pts = view({upright_box(0.0, 0.0, 0.0, {0.100, 0.056, 0.038}, 0.3),
                           upright_box(-0.002, 0.001, 0.038, {0.112, 0.066, 0.029}, 0.35)},
                          0.0, 0.0, 0.15);
  const std::vector<SideStep> steps = side_steps(pts, 0.0);
  REQUIRE(steps.size() == 1);
  CHECK(steps[0].z == Approx(0.038).margin(0.004));
  CHECK(steps[0].lower_top <= steps[0].z);
  const auto boxes = fit_stacked_boxes(pts);
  REQUIRE(boxes.size() == 2);
  CHECK(boxes[0].size.z() == Approx(0.038).margin(0.004));
  CHECK(std::max(boxes[0].size.x(), boxes[0].size.y()) == Approx(0.100).margin(0.005));
  CHECK(std::min(boxes[0].size.x(), boxes[0].size.y()) == Approx(0.056).margin(0.005));
  CHECK(bottom_of(boxes[1]) == Approx(0.038).margin(0.004));
  CHECK(boxes[1].size.z() == Approx(0.029).margin(0.004));
  CHECK(std::max(boxes[1].size.x(), boxes[1].size.y()) == Approx(0.112).margin(0.005));
  CHECK(std::min(boxes[1].size.x(), boxes[1].size.y()) == Approx(0.066).margin(0.005));
  // Without the side steps the stack is one box of the two heights.
  StackOptions off;
  off.sides.enabled = false;
  const auto one = fit_stacked_boxes(pts, {}, off);
  REQUIRE(one.size() == 1);
  CHECK(one[0].size.z() == Approx(0.067).margin(0.004));
}

TEST_CASE("side steps: a single box stays one box, in full view and half hidden", "[perception][stack][sides]") {
  SECTION("in full view, with depth noise") {
    const Points pts = view({upright_box(0.0, 0.0, 0.0, {0.07, 0.09, 0.16}, 0.5)}, 0.0, 0.0, 0.1);
    CHECK(side_steps(pts, 0.0).empty());
    CHECK(fit_stacked_boxes(pts).size() == 1);
  }
  SECTION("its lower half behind a box in front, which is not in the cluster") {
    // The front box, 8 cm tall, hides the lower part of one face only.
    const Points pts = view({upright_box(0.0, 0.0, 0.0, {0.07, 0.09, 0.16}, 0.5), upright_box(0.07, -0.09, 0.0, {0.06, 0.05, 0.08}, 0.2)},
                            0.0, 0.0, 0.06);
    CHECK(side_steps(pts, 0.0).empty());
    CHECK(fit_stacked_boxes(pts).size() == 1);
  }
}

TEST_CASE("side steps: one face under a step is not a box; two faces are", "[perception][stack][sides]") {
  // An upper box 100 x 60 x 30 mm resting at 40 mm: its top and the two faces towards -x and
  // -y. Under it, the lower box's face towards -y, 8 mm in from the upper one's, and in the
  // second case also its face towards -x, 6 mm in.
  Points upper;
  const double step = 0.002;
  for (double x = -0.05; x <= 0.05; x += step)
    for (double y = -0.03; y <= 0.03; y += step) upper.emplace_back(x, y, 0.07);
  for (double z = 0.04; z < 0.07; z += step) {
    for (double x = -0.05; x <= 0.05; x += step) upper.emplace_back(x, -0.03, z);
    for (double y = -0.03; y <= 0.03; y += step) upper.emplace_back(-0.05, y, z);
  }
  Points one_face = upper, two_faces = upper;
  for (double z = 0.013; z < 0.04; z += step) {
    for (double x = -0.044; x <= 0.044; x += step) {
      one_face.emplace_back(x, -0.022, z);
      two_faces.emplace_back(x, -0.022, z);
    }
    for (double y = -0.022; y <= 0.024; y += step) two_faces.emplace_back(-0.044, y, z);
  }
  const SideStepOptions o;
  REQUIRE(side_steps(one_face, 0.0, o).size() == 1);
  const auto alone = fit_column(one_face, 0.0, {}, o);
  REQUIRE(alone.size() == 1);
  CHECK(bottom_of(alone[0]) == Approx(0.04).margin(0.004));  // resting on what the cloud hides
  CHECK(alone[0].size.z() == Approx(0.03).margin(0.004));
  const auto both = fit_column(two_faces, 0.0, {}, o);
  REQUIRE(both.size() == 2);
  CHECK(std::max(both[0].size.x(), both[0].size.y()) == Approx(0.088).margin(0.005));
  CHECK(std::min(both[0].size.x(), both[0].size.y()) == Approx(0.046).margin(0.005));
  CHECK(bottom_of(both[1]) == Approx(0.04).margin(0.004));
}
