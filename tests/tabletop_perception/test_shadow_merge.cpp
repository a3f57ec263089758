// Clusters split by a resting box's shadow (shadow_merge.h): the far part of a top that a
// box lying across it hides from the sensor is joined to the near part; a top seen from
// overhead, a far part with something on it, a tall box's side face crossing the plane's
// height, and (with the cloud's rays) a neighbour with the table seen between are not.
#include <catch2/catch.hpp>

#include "stdlib/tabletop/perception/shadow_merge.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::FreeSpace;
using ksmc::stdlib::tabletop::RayIndex;

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

namespace {

using ksmc::tests::perception::CastBox;
using ksmc::tests::perception::upright_box;

const Eigen::Vector3d kHigh(0.0, -0.3, 1.0);

// A view of `boxes` from kHigh (ray cast, 3 mm at 1 m): the rays, and per box the points on
// it (within 1 mm; the table's points are on none).
struct View {
  RayIndex rays;
  std::vector<Points> on;
};
View seen(const std::vector<CastBox>& boxes) {
  FreeSpace fs;
  fs.sensor = kHigh;
  fs.points = ksmc::tests::perception::cast_view(kHigh, Eigen::Vector3d(0.05, 0.05, 0.03), 0.45, 0.003, boxes, 0.5, 0.5);
  View v;
  v.on.resize(boxes.size());
  for (const auto& p : fs.points)
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      const Eigen::Vector3d l = boxes[b].pose.inverse() * p;
      if ((l.cwiseAbs() - 0.5 * boxes[b].size).maxCoeff() <= 0.001) {
        v.on[b].push_back(p);
        break;
      }
    }
  v.rays = RayIndex(std::move(fs));
  return v;
}

// A box lying across the lower top: 20 x 4 x 4 cm, y from -1 to 3 cm, on a 6 cm top.
const CastBox kAcross = upright_box(0.0, 0.01, 0.06, Eigen::Vector3d(0.2, 0.04, 0.04));

}  // namespace

TEST_CASE("shadow merge: a neighbour of the same height with the table seen between is not the far part",
          "[perception][shadow]") {
  // Box a (6 cm) ends just past the box lying across it; box b (6 cm) starts beyond that box's
  // shadow and reaches 20 cm further along x, so the table is seen inside the hull of the two tops.
  const CastBox a = upright_box(0.0, -0.0325, 0.0, Eigen::Vector3d(0.2, 0.135, 0.06));
  const CastBox b = upright_box(0.1, 0.125, 0.0, Eigen::Vector3d(0.4, 0.15, 0.06));
  const View v = seen({a, kAcross, b});
  Points near = v.on[0];
  near.insert(near.end(), v.on[1].begin(), v.on[1].end());
  const Points& far = v.on[2];
  // The shadow test alone takes b for the far part of a's top.
  REQUIRE(merge_shadow_split({near, far}, kHigh).size() == 1);
  CHECK(merge_shadow_split({near, far}, kHigh, {}, &v.rays).size() == 2);
  // One long box under the one lying across it: the rays end on its top, so it is joined.
  const View one = seen({upright_box(0.0, 0.05, 0.0, Eigen::Vector3d(0.2, 0.3, 0.06)), kAcross});
  Points top_near, top_far;
  for (const auto& p : one.on[0]) (p.y() < 0.0 ? top_near : top_far).push_back(p);
  top_near.insert(top_near.end(), one.on[1].begin(), one.on[1].end());
  CHECK(merge_shadow_split({top_near, top_far}, kHigh, {}, &one.rays).size() == 1);
}
