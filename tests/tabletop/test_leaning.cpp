// leaning: a tilted box held as a leaning box is, by a surface under it and a body on the side
// it would fall to (blocks::obb::leaning, the evidence of domains/tabletop.ksm's r25).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/extract_higher.h"
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
  cut.objects = {wall(), board(20.0, 0.025)};  // 2.5 cm into the wall: past sqrt(2) x the 15 mm fallback
  CHECK_FALSE(leaning(cut, 2));
}

TEST_CASE("leaning: the body it leans on may be cut into within the scene's pose noise", "[geometry]") {
  // Pose noise puts a leaning box's estimate on either side of the face it leans on. With
  // fewer than 3 resting gaps the scene's vertical tolerance is the stdlib's 15 mm: a board
  // 1 cm into the wall leans; 2.5 cm into it (above, past sqrt(2) x 15 mm) does not.
  Scene noisy;
  noisy.objects = {wall(), board(20.0, 0.01)};
  REQUIRE(blocks::Scene(noisy).vertical_tolerance() == Approx(0.015));
  CHECK(leaning(noisy, 2));

  // Three cubes resting exactly on the table: no gap noise, the tolerance falls to the 5 mm
  // intersect tolerance, and the same 1 cm cut is no lean.
  Scene exact = noisy;
  for (int i = 0; i < 3; ++i)
    exact.objects.push_back(object("cube" + std::to_string(i), Vector3d(-0.5, 0.2 * i, 0.05), Vector3d(0.1, 0.1, 0.1)));
  REQUIRE(blocks::Scene(exact).vertical_tolerance() == Approx(0.005));
  CHECK_FALSE(leaning(exact, 2));
  // The cut is the difference of two estimates, each within the tolerance: up to sqrt(2) x
  // 5 mm = 7.1 mm. 6 mm leans (it did not with 5 mm allowed: the cloud front end's leaning
  // boxes cut 4-6 mm into what they lean on); 8 mm does not.
  exact.objects[1] = board(20.0, 0.006);
  CHECK(leaning(exact, 2));
  exact.objects[1] = board(20.0, 0.008);
  CHECK_FALSE(leaning(exact, 2));
  // The surface under it may not be cut into: the board 2 cm deep in the table.
  Scene sunk;
  SceneObject deep = board(20.0);
  deep.pose.t.z() -= 0.02;
  sunk.objects = {wall(), deep};
  CHECK_FALSE(leaning(sunk, 2));
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

namespace {

// A 20 x 10 x 6 cm box lying tilted by 14 deg, its raised end towards +x: the -x edge of its
// bottom face on the table at x = 0 (lifted by `lift`), and its bottom face resting on the -x
// top edge of a flat 10 x 10 x 2.5 cm box (2.5 cm + lift tall), 1 cm beyond the box's centre of
// mass: at rest on two supports. It is `higher` than the flat box (its bottom face centre is
// within the tolerance of the flat box's top), as in the generated scenes.
Scene propped(double lift) {
  const double t = 14.0 * 3.14159265358979323846 / 180.0, hx = 0.10, hz = 0.03, h = 0.025;
  const double c = std::cos(t), s = std::sin(t);
  const Vector3d centre(hx * c - hz * s, 0.0, hx * s + hz * c + lift);
  const double edge = h / std::tan(t);  // where the bottom face is h above its lowest edge
  Scene scene;
  scene.objects = {object("box", centre, Vector3d(2 * hx, 0.1, 2 * hz), rot(-14.0, Vector3d::UnitY())),
                   object("flat", Vector3d(edge + 0.05, 0.0, 0.5 * (h + lift)), Vector3d(0.1, 0.1, h + lift))};
  return scene;
}

}  // namespace

TEST_CASE("leaning: propped on a flat box beyond its centre, its foot on the table", "[geometry]") {
  // The flat box under its raised end is on the side it would fall to; the box is `higher`
  // than it, so the flat box is a surface under it as well. The table is the other body.
  const Scene on_table = propped(0.0);
  const blocks::Scene s(on_table);
  REQUIRE(extract_higher(s.box(1), s.box(2), EvidenceParams{}));
  REQUIRE(blocks::touching(s, 1, 0, kEps));  // the foot on the table
  REQUIRE(blocks::touching(s, 1, 2, kEps));  // the bottom face on the flat box's edge
  CHECK(blocks::obb::leaning(s, 1, kTol, kEps));

  // Foot 2 cm above the table, on the (taller) flat box alone: one body cannot both carry it
  // and hold it on the side it falls to.
  const Scene lifted = propped(0.02);
  const blocks::Scene l(lifted);
  REQUIRE_FALSE(blocks::touching(l, 1, 0, kEps));
  REQUIRE(blocks::touching(l, 1, 2, kEps));
  CHECK_FALSE(blocks::obb::leaning(l, 1, kTol, kEps));
}

TEST_CASE("depth noise: a scene that states its sensor's noise takes its tolerances from it", "[geometry]") {
  // Three boxes seated exactly on the table, as the cloud front end seats them: their gaps
  // are 0 and say nothing of the noise (tolerance 5 mm, the floor). With the depth noise
  // stated, the tolerance is 3 sigma within [5 mm, 15 mm] and gap_sigma is sigma.
  Scene s;
  for (int i = 0; i < 3; ++i)
    s.objects.push_back(object("b" + std::to_string(i), Vector3d(0.2 * i, 0, 0.025), Vector3d(0.1, 0.1, 0.05)));
  CHECK(blocks::Scene(s).vertical_tolerance() == Approx(0.005));
  CHECK(blocks::Scene(s).gap_sigma() == 0.0);
  s.depth_noise = 0.0023;
  CHECK(blocks::Scene(s).vertical_tolerance() == Approx(0.0069));
  CHECK(blocks::Scene(s).gap_sigma() == Approx(0.0023));
  s.depth_noise = 0.001;
  CHECK(blocks::Scene(s).vertical_tolerance() == Approx(0.005));
  s.depth_noise = 0.01;
  CHECK(blocks::Scene(s).vertical_tolerance() == Approx(0.015));
  CHECK(blocks::Scene(s).gap_sigma() == Approx(0.005));  // a third of the tolerance at most
}
