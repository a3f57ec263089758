// snugger: which of two boxes sits on what it rests on with the smaller gap
// (blocks::obb::snugger, the evidence of domains/tabletop.ksm's r26).
#include <catch2/catch.hpp>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using Eigen::Vector3d;

namespace {

constexpr double kEps = 0.004;
constexpr double kMargin = 1.0;  // in units of the scene's gap noise

// A 10 cm cube with its bottom `gap` above the table, its centre at x.
SceneObject cube(const char* id, double x, double gap) {
  return object(id, Vector3d(x, 0.0, 0.05 + gap), Vector3d(0.1, 0.1, 0.1));
}

bool snugger(const Scene& input, std::int32_t a, std::int32_t b) {
  const blocks::Scene s(input);
  return blocks::obb::snugger(s, a, b, kEps, kMargin);
}

}  // namespace

TEST_CASE("snugger: of two cubes on the table cutting each other, the one with the smaller gap", "[geometry]") {
  Scene input;
  input.objects = {cube("a", 0.0, 0.001), cube("b", 0.08, 0.011)};  // cut 2 cm sideways
  const blocks::Scene s(input);
  // Two gaps are too few to judge the scene's noise: one sigma is a third of the largest
  // vertical tolerance, 5 mm.
  REQUIRE(s.gap_sigma() == Approx(0.005));
  CHECK(snugger(input, 1, 2));  // 1 mm + 5 mm < 11 mm
  CHECK_FALSE(snugger(input, 2, 1));
  CHECK_FALSE(snugger(input, 1, 1));
  CHECK_FALSE(snugger(input, 0, 1));  // the table rests on nothing
  CHECK_FALSE(snugger(input, 1, 0));
  // Within one sigma of each other: neither.
  input.objects[1] = cube("b", 0.08, 0.005);
  CHECK_FALSE(snugger(input, 1, 2));
  CHECK_FALSE(snugger(input, 2, 1));
  // Sunk into the table counts as a gap as well.
  input.objects[1] = cube("b", 0.08, -0.009);
  CHECK(snugger(input, 1, 2));
}

TEST_CASE("snugger: a box on another box measures its gap to that box's top", "[geometry]") {
  Scene input;
  input.objects = {cube("base", 0.0, 0.0), object("top", Vector3d(0.0, 0.0, 0.1 + 0.004 + 0.02), Vector3d(0.06, 0.06, 0.04)),
                   cube("side", 0.2, 0.001)};
  // Three resting gaps, 0, 4 and 1 mm: one sigma is 1.4826 x the median, 1.48 mm.
  const blocks::Scene s(input);
  REQUIRE(s.gap_sigma() == Approx(1.4826 * 0.001).epsilon(1e-3));
  CHECK(snugger(input, 3, 2));  // 1 mm on the table, 4 mm above the base
  CHECK(snugger(input, 1, 2));
  CHECK_FALSE(snugger(input, 2, 3));
  CHECK_FALSE(snugger(input, 1, 3));  // 0 and 1 mm: within a sigma
}

TEST_CASE("snugger: not for a box on nothing visible (it may rest on a hidden one)", "[geometry]") {
  Scene input;
  input.objects = {cube("a", 0.0, 0.001), cube("b", 0.08, 0.03)};  // 3 cm above the table
  CHECK_FALSE(snugger(input, 1, 2));
  CHECK_FALSE(snugger(input, 2, 1));
}

TEST_CASE("snugger: a box cut into from the side is no seat", "[geometry]") {
  // A 4 cm cube pushed 3 mm sideways into a 10 cm cube's top edge, its bottom 7 mm below that
  // cube's top: it lies `higher` than the cube (15 mm tolerance) and overlaps it, but on a
  // side, so it rests on nothing visible. Read as a seat, its 7 mm gap would make the cube on
  // the table the snugger one.
  Scene input;
  input.objects = {cube("a", 0.0, 0.0), object("c", Vector3d(0.05 + 0.02 - 0.003, 0.0, 0.1 - 0.007 + 0.02), Vector3d(0.04, 0.04, 0.04))};
  CHECK_FALSE(snugger(input, 1, 2));
  CHECK_FALSE(snugger(input, 2, 1));
}

TEST_CASE("snugger: a move and its undo are seen (the per-body seat gaps are not kept across them)", "[geometry]") {
  Scene input;
  input.objects = {cube("a", 0.0, 0.001), cube("b", 0.08, 0.011)};
  blocks::Scene s(input);
  CHECK(blocks::obb::snugger(s, 1, 2, kEps, kMargin));
  Pose lowered = input.objects[1].pose;
  lowered.t.z() -= 0.01;  // b down to 1 mm above the table
  s.set_pose(2, lowered);
  CHECK_FALSE(blocks::obb::snugger(s, 1, 2, kEps, kMargin));
  s.undo();
  CHECK(blocks::obb::snugger(s, 1, 2, kEps, kMargin));
  s.set_pose(2, lowered);
  s.commit();
  CHECK_FALSE(blocks::obb::snugger(s, 1, 2, kEps, kMargin));
}
