// leaning: a tilted box held as a leaning box is, by a surface under it and a body on the side
// it would fall to (blocks::obb::leaning, the evidence of domains/tabletop.ksm's r25).
#include <catch2/catch.hpp>

#include <cmath>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

constexpr double kTol = 10.0 * 3.14159265358979323846 / 180.0;
constexpr double kEps = 0.004;
constexpr double kWallX = 0.1;  // the wall's -x face

// A 10 x 10 x 20 cm wall standing on the table, its -x face at x = kWallX.
SceneObject wall() { return object("wall", Vector3d(kWallX + 0.05, 0.0, 0.1), Vector3d(0.1, 0.1, 0.2)); }

// A 2 x 10 x 20 cm board turned `deg` about y (its top towards +x for deg > 0), its lowest edge
// on the table and its farthest +x edge at x = kWallX + push (push < 0: clear of the wall,
// push > 0: cutting into it).
SceneObject board(double deg, double push = 0.0) {
  const double a = deg * 3.14159265358979323846 / 180.0;
  const double hx = 0.01, hz = 0.1;
  const Vector3d c(kWallX + push - (hx * std::cos(a) + hz * std::sin(a)), 0.0, hx * std::sin(a) + hz * std::cos(a));
  return object("board", c, Vector3d(2 * hx, 0.1, 2 * hz), rot(deg, Vector3d::UnitY()));
}

bool leaning(const Scene& input, std::int32_t body) {
  const blocks::Scene s(input);
  return blocks::obb::leaning(s, body, kTol, kEps);
}

}  // namespace

TEST_CASE("leaning: a board against a wall, on the table", "[geometry]") {
  Scene input;
  input.objects = {wall(), board(20.0)};
  CHECK(leaning(input, 2));
  CHECK_FALSE(leaning(input, 1));  // the wall rests on a face
  CHECK_FALSE(leaning(input, 0));  // the table
  // 2 mm short of the wall: still touching within eps.
  input.objects[1] = board(20.0, -0.002);
  CHECK(leaning(input, 2));
}

TEST_CASE("leaning: not without the body it leans on, nor when cutting into it", "[geometry]") {
  Scene alone;
  alone.objects = {board(20.0)};
  CHECK_FALSE(leaning(alone, 1));  // only the table under it: it would fall

  Scene apart;
  apart.objects = {wall(), board(20.0, -0.02)};  // 2 cm short of the wall
  CHECK_FALSE(leaning(apart, 2));

  Scene cut;
  cut.objects = {wall(), board(20.0, 0.02)};  // 2 cm into the wall
  CHECK_FALSE(leaning(cut, 2));
}

TEST_CASE("leaning: the body it touches must be on the side it would fall to", "[geometry]") {
  // The board tilted away from the wall (its top towards -x), touching the wall with its foot:
  // nothing holds it on the side it falls to.
  const double a = 20.0 * 3.14159265358979323846 / 180.0;
  const double hx = 0.01, hz = 0.1;
  Scene away;
  const Vector3d c(kWallX - 0.001 - (hx * std::cos(a) + hz * std::sin(a)), 0.0, hx * std::sin(a) + hz * std::cos(a));
  away.objects = {wall(), object("board", c, Vector3d(2 * hx, 0.1, 2 * hz), rot(-20.0, Vector3d::UnitY()))};
  const blocks::Scene s(away);
  REQUIRE(blocks::touching(s, 2, 1, kEps));  // it does touch the wall
  CHECK_FALSE(blocks::obb::leaning(s, 2, kTol, kEps));
}

TEST_CASE("leaning: standing on a box counts as a surface under it", "[geometry]") {
  // A 4 cm slab under the board's foot and the wall: the board stands on the slab.
  Scene input;
  SceneObject raised = board(20.0);
  raised.pose.t.z() += 0.04;
  SceneObject tall = wall();
  tall.size.z() = 0.3;
  tall.pose.t.z() = 0.15;
  input.objects = {tall, object("slab", Vector3d(0.0, 0.0, 0.02), Vector3d(0.2, 0.2, 0.04)), raised};
  CHECK(leaning(input, 3));
}
