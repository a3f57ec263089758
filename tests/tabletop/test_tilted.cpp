// tilted: a box tilted beyond the scene's resting-tilt noise (tilt_noise.h,
// blocks::obb::tilted; the evidence of domains/tabletop.ksm's r31).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/tilt_noise.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kStableTol = 10.0 * kDeg;

// A 10 cm cube on the table at x, tilted `deg` about the y axis.
SceneObject cube(const char* id, double x, double deg) {
  return object(id, Vector3d(x, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1), rot(deg, Vector3d::UnitY()));
}

}  // namespace

TEST_CASE("tilt noise: the Rayleigh scale of the median tilt of the boxes resting on a face", "[geometry]") {
  Scene input;
  for (const auto& [id, deg] : {std::pair{"a", 0.4}, std::pair{"b", 1.0}, std::pair{"c", 0.6}})
    input.objects.push_back(cube(id, 0.3 * static_cast<double>(input.objects.size()), deg));
  input.objects.push_back(cube("leaning", 1.0, 30.0));  // beyond the stable tolerance: not counted
  const TiltNoise n = tilt_noise(input, kStableTol);
  CHECK(n.tilts == 3);
  CHECK(n.sigma == Approx(0.6 * kDeg / std::sqrt(2.0 * std::log(2.0))));  // median 0.6 deg
  input.objects.push_back(cube("d", 1.3, 0.8));  // an even count: the mean of the middle two
  CHECK(tilt_noise(input, kStableTol).sigma == Approx(0.7 * kDeg / std::sqrt(2.0 * std::log(2.0))));
  CHECK(tilt_noise(Scene{}, kStableTol).tilts == 0);
}

TEST_CASE("tilted: beyond k sigma of the scene's tilt noise and the minimum angle", "[geometry]") {
  Scene input;
  for (const auto& [id, deg] : {std::pair{"a", 0.4}, std::pair{"b", 1.0}, std::pair{"c", 0.6}, std::pair{"d", 0.8}})
    input.objects.push_back(cube(id, 0.3 * static_cast<double>(input.objects.size()), deg));
  input.objects.push_back(cube("slant", 1.5, 5.0));
  input.objects.push_back(cube("slight", 1.8, 1.5));
  const blocks::Scene s(input);
  // Median of 0.4, 0.6, 0.8, 1.0, 1.5, 5 deg: 0.9 deg, sigma 0.76 deg, 3 sigma 2.3 deg.
  CHECK(s.tilt_sigma() == Approx(0.9 * kDeg / std::sqrt(2.0 * std::log(2.0))));
  auto tilted = [&](std::int32_t body, double k, double min_deg) {
    return blocks::obb::tilted(s, s.se3(body), s.vec3(body), k, min_deg * kDeg);
  };
  CHECK(tilted(5, 3.0, 2.0));         // slant: 5 deg
  CHECK_FALSE(tilted(6, 3.0, 0.0));   // slight: 1.5 deg, within 3 sigma
  CHECK(tilted(6, 1.0, 0.0));         // but beyond one sigma
  CHECK_FALSE(tilted(5, 3.0, 6.0));   // the minimum angle
  CHECK_FALSE(tilted(0, 3.0, 2.0));   // the table
}

TEST_CASE("tilted: never with fewer than 3 boxes resting on a face", "[geometry]") {
  Scene input;
  input.objects.push_back(cube("a", 0.0, 0.0));
  input.objects.push_back(cube("slant", 0.3, 8.0));
  const blocks::Scene s(input);
  CHECK(s.tilt_sigma() == std::numeric_limits<double>::infinity());
  CHECK_FALSE(blocks::obb::tilted(s, s.se3(2), s.vec3(2), 3.0, 2.0 * kDeg));
}
