// Clusters split by a resting box's shadow (shadow_merge.h): the far part of a top that a
// box lying across it hides from the sensor is joined to the near part; a top seen from
// overhead, a far part with something on it, and a tall box's side face crossing the
// plane's height are not.
#include <catch2/catch.hpp>

#include "stdlib/tabletop/perception/shadow_merge.h"

using namespace ksmc::stdlib::tabletop::perception;

namespace {

void add_top(Points& pts, double x0, double x1, double y0, double y1, double z) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.003)
    for (double y = y0; y <= y1 + 1e-9; y += 0.003) pts.emplace_back(x, y, z);
}
// A vertical face at y = y0 facing -y.
void add_face(Points& pts, double x0, double x1, double y0, double z0, double z1) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.003)
    for (double z = z0; z <= z1 + 1e-9; z += 0.003) pts.emplace_back(x, y0, z);
}

// The near part of a lower box's top (z = 6 cm) with a box lying across it (4 cm high,
// y from -1 to 3 cm).
Points near_part() {
  Points a;
  add_top(a, -0.1, 0.1, -0.07, -0.013, 0.06);
  add_face(a, -0.1, 0.1, -0.01, 0.063, 0.1);
  add_top(a, -0.1, 0.1, -0.01, 0.03, 0.1);
  return a;
}
// The far part of the lower box's top, beyond the shadow (which, from the low sensor, ends
// at y = 12.8 cm).
Points far_part() {
  Points b;
  add_top(b, -0.1, 0.1, 0.135, 0.2, 0.06);
  return b;
}

const Eigen::Vector3d kLow(0.0, -1.0, 0.5);

}  // namespace

TEST_CASE("shadow merge: the far part of a top behind a box lying across it is joined", "[perception][shadow]") {
  const Points a = near_part(), b = far_part();
  const auto merged = merge_shadow_split({a, b}, kLow);
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].size() == a.size() + b.size());
  ShadowMergeOptions off;
  off.enabled = false;
  CHECK(merge_shadow_split({a, b}, kLow, off).size() == 2);
}

TEST_CASE("shadow merge: what is not a shadow split stays apart", "[perception][shadow]") {
  const Points a = near_part(), b = far_part();
  // Seen from overhead the box's shadow ends at its own far side: the gap was seen.
  CHECK(merge_shadow_split({a, b}, Eigen::Vector3d(0.0, 0.0, 1.0)).size() == 2);
  // Something stands on the far part: it is not a bare top.
  Points covered = b;
  add_top(covered, -0.02, 0.02, 0.16, 0.18, 0.09);
  CHECK(merge_shadow_split({a, covered}, kLow).size() == 2);
  // A tall box (20 cm) whose near face crosses 6 cm: a face is not a top.
  Points tall;
  add_face(tall, -0.05, 0.05, -0.05, 0.0, 0.2);
  add_top(tall, -0.05, 0.05, -0.05, 0.0, 0.2);
  CHECK(merge_shadow_split({tall, b}, kLow).size() == 2);
}
