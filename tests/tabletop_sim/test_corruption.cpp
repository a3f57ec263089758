// Hidden/false construction on hand-made configurations.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numbers>

#include "tools/tabletop_sim/corruption.h"

using namespace ksmc::tools::tabletop_sim;

namespace {
Box make_box(Eigen::Vector3d size, Eigen::Vector3d t, Eigen::Quaterniond q = Eigen::Quaterniond::Identity()) {
  Box b;
  b.size = size;
  b.pose.t = t;
  b.pose.q = q;
  return b;
}
// A three-high stack plus a lone box on the table.
std::vector<Box> stack3() {
  return {make_box({0.2, 0.2, 0.04}, {0, 0, 0.02}), make_box({0.15, 0.1, 0.05}, {0, 0, 0.065}),
          make_box({0.1, 0.06, 0.03}, {0, 0, 0.105}), make_box({0.1, 0.1, 0.1}, {0.3, 0, 0.05})};
}
}  // namespace

TEST_CASE("Removing supporters hides the boxes above them", "[tabletop_sim][corruption]") {
  const auto boxes = stack3();
  const Relations rel = compute_relations(boxes, RelationParams{});
  REQUIRE(rel.support == std::vector<std::pair<int, int>>{{0, kTableIndex}, {1, 0}, {2, 1}, {3, kTableIndex}});

  CorruptionParams p;
  p.hidden_rate = 0.0;
  Rng rng(1);
  CHECK(choose_undetected(rng, boxes, rel, p) == std::vector<bool>{false, false, false, false});

  p.hidden_rate = 1.0;  // every supporter goes, in order: 0 (hides 1), then 1 (hides 2)
  const auto removed = choose_undetected(rng, boxes, rel, p);
  CHECK(removed == std::vector<bool>{true, true, false, false});
  CHECK(hidden_boxes(boxes.size(), rel, removed) == std::vector<bool>{false, false, true, false});

  // Only the middle one missing: the top box is hidden, the bottom one is not.
  const std::vector<bool> middle{false, true, false, false};
  CHECK(hidden_boxes(boxes.size(), rel, middle) == std::vector<bool>{false, false, true, false});
  CHECK(estimate_is_consistent(boxes, rel, middle, p));
}

TEST_CASE("A removal that would leave a box hovering unexplained is refused", "[tabletop_sim][corruption]") {
  // Box 1 lies tilted across the top of box 0 without touching the table: contact only.
  std::vector<Box> boxes{make_box({0.1, 0.1, 0.1}, {0, 0, 0.05}),
                         make_box({0.2, 0.05, 0.02}, {0, 0, 0.0},
                                  Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY())))};
  // Put the plank's lowest vertex over the middle of box 0, 0.5 mm above its top.
  const auto verts = box_vertices(boxes[1]);
  const auto low = *std::min_element(verts.begin(), verts.end(), [](const auto& a, const auto& b) { return a.z() < b.z(); });
  boxes[1].pose.t += Eigen::Vector3d(-low.x(), -low.y(), 0.1 + 0.0005 - low.z());
  const Relations rel = compute_relations(boxes, RelationParams{});
  REQUIRE(rel.contact == std::vector<std::pair<int, int>>{{0, 1}});
  CorruptionParams p;
  CHECK_FALSE(estimate_is_consistent(boxes, rel, {true, false}, p));
  p.hidden_rate = 1.0;
  Rng rng(2);
  // Box 0 supports nothing, so it is no candidate anyway; the consistency check is what keeps
  // a moved estimate of box 0 from being drawn.
  CHECK(choose_undetected(rng, boxes, rel, p) == std::vector<bool>{false, false});
}

TEST_CASE("False estimates are placed as requested", "[tabletop_sim][corruption]") {
  CorruptionParams p;
  Rng rng(4);
  BoxItem item;
  item.size = Eigen::Vector3d(0.12, 0.08, 0.06);
  const Box target = make_box({0.2, 0.07, 0.3}, {0, 0, 0.15});
  for (int i = 0; i < 20; ++i) {
    const auto b = place_intersecting(rng, item, target, p);
    REQUIRE(b);
    CHECK(sat_overlap(*b, target) >= p.min_penetration - 1e-6);
    CHECK(sat_overlap(*b, target) <= p.max_penetration + 1e-6);
    CHECK(lowest_z(*b) >= -0.002);
  }
  const std::vector<Box> others{target, make_box({0.1, 0.1, 0.1}, {0.15, 0.1, 0.05})};
  for (int i = 0; i < 20; ++i) {
    const auto b = place_floating(rng, item, others, {0.25, 0.2}, p);
    REQUIRE(b);
    CHECK(lowest_z(*b) >= p.min_float_gap - 1e-9);
    CHECK(tilt_from_vertical(b->pose.q) >= p.min_float_tilt - 1e-9);
    for (const Box& o : others) CHECK(box_distance(*b, o) >= p.min_float_gap - 1e-4);
  }
}

TEST_CASE("Pose noise has the configured RMS size", "[tabletop_sim][corruption]") {
  CorruptionParams p;
  Rng rng(9);
  Pose base;
  base.t = Eigen::Vector3d(0.1, 0.2, 0.3);
  double st = 0, sr = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const Pose q = add_pose_noise(rng, base, p);
    st += (q.t - base.t).squaredNorm();
    sr += std::pow(rotation_angle(q.q, base.q), 2);
  }
  CHECK(std::sqrt(st / n) == Approx(p.sigma_translation).epsilon(0.05));
  CHECK(std::sqrt(sr / n) == Approx(p.sigma_rotation).epsilon(0.05));
}
