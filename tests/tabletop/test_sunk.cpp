// sunk: a box whose lowest point lies inside the table beyond the scene's gap noise
// (blocks::obb::sunk; the evidence of domains/tabletop.ksm's r33).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMin = 0.004;

// A 10 cm cube at x, turned `deg` about the y axis, its lowest edge `depth` [m] below the table top.
SceneObject cube(const char* id, double x, double deg, double depth) {
  const double t = deg * kDeg;
  const double reach = 0.05 * (std::cos(t) + std::sin(t));  // centre to lowest edge, vertically
  return object(id, Vector3d(x, 0.0, reach - depth), Vector3d(0.1, 0.1, 0.1), rot(deg, Vector3d::UnitY()));
}

}  // namespace

TEST_CASE("sunk: the lowest point below the table top by more than k sigma of the gap noise and the minimum",
          "[geometry]") {
  Scene input;
  // Four level cubes resting with gaps of -1 to 2 mm: the scene's gap noise.
  for (const auto& [id, gap] : {std::pair{"a", 0.001}, std::pair{"b", -0.001}, std::pair{"c", 0.002}, std::pair{"d", 0.0}})
    input.objects.push_back(cube(id, 0.3 * static_cast<double>(input.objects.size()), 0.0, -gap));
  // Depths relative to the threshold are set once the scene's noise is known.
  const double sigma = blocks::Scene(input).gap_sigma();
  REQUIRE(sigma > 0.0);
  const double threshold = std::max(1.5 * sigma, kMin);
  input.objects.push_back(cube("deep", 1.5, 20.0, threshold + 0.002));
  input.objects.push_back(cube("shallow", 1.8, 20.0, threshold - 0.002));
  input.objects.push_back(cube("level_deep", 2.1, 0.0, threshold + 0.002));
  const blocks::Scene s(input);
  // The tilted boxes are not resting on a face, and the median |gap| (gap_noise.h) ignores the deep level one.
  REQUIRE(s.gap_sigma() == Approx(sigma));
  auto sunk = [&](std::int32_t body, double k, double min) { return blocks::obb::sunk(s, s.se3(body), s.vec3(body), k, min); };
  CHECK(sunk(5, 1.5, kMin));          // deep: its lowest edge 2 mm past the threshold
  CHECK_FALSE(sunk(6, 1.5, kMin));    // shallow: 2 mm short of it
  CHECK(sunk(6, 0.0, 0.0));           // but below the table top
  CHECK(sunk(7, 1.5, kMin));          // a level box sunk as deep: the evidence reads depth only (r33 adds `tilted`)
  CHECK_FALSE(sunk(5, 1.5, 0.05));    // the minimum depth
  for (std::int32_t b = 1; b <= 4; ++b) CHECK_FALSE(sunk(b, 1.5, kMin));  // resting right
  CHECK_FALSE(sunk(0, 0.0, 0.0));     // the table
}
