// tilted_foot: a leaning box seen only above the box in front of it grows down to the table
// where the rays say its lower part is hidden; seen empty, or cutting into a box, it does not.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/obb_sat.h"
#include "stdlib/tabletop/perception/tilted_foot.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::FreeSpace;
using ksmc::stdlib::tabletop::Obb;
using ksmc::stdlib::tabletop::RayIndex;
using ksmc::tests::perception::CastBox;
using ksmc::tests::perception::cast_view;
using ksmc::tests::perception::on_table;
using ksmc::tests::perception::upright_box;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const Eigen::Vector3d kSensor(0.0, -0.8, 0.6);

// A 6 x 5 x 24 cm box (local z: its length) leaning 25 degrees back (+y) about x, its lowest
// edge on the table, its centre over the origin.
CastBox leaning() {
  const Eigen::Vector3d size(0.06, 0.05, 0.24);
  return {on_table(Eigen::AngleAxisd(-25.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix(), size), size};
}

UprightBox as_box(const CastBox& c) {
  UprightBox b;
  b.size = c.size;
  b.pose.t = c.pose.translation();
  b.pose.q = Eigen::Quaterniond(c.pose.linear());
  return b;
}

// The leaning box as fitted from its upper `seen` m only.
UprightBox upper_part(const CastBox& c, double seen) {
  UprightBox b = as_box(c);
  b.size.z() = seen;
  b.pose.t += 0.5 * (c.size.z() - seen) * c.pose.linear().col(2);
  return b;
}

RayIndex rays_of(const std::vector<CastBox>& boxes) {
  FreeSpace seen;
  seen.points = cast_view(kSensor, Eigen::Vector3d(0.0, 0.05, 0.05), 0.35, 0.0015, boxes, 0.5, 0.4);
  seen.sensor = kSensor;
  return RayIndex(seen);
}

}  // namespace

TEST_CASE("tilted foot: a leaning box seen above the box in front of it reaches the table", "[perception][tilted]") {
  const CastBox lean = leaning();
  const CastBox front = upright_box(0.0, -0.125, 0.0, Eigen::Vector3d(0.14, 0.06, 0.21));
  const RayIndex rays = rays_of({front, lean});
  std::vector<UprightBox> boxes{as_box(front), upper_part(lean, 0.08)};
  REQUIRE(Obb::from_pose(boxes[1].pose, boxes[1].size).min_z() > 0.1);
  CHECK(grow_tilted_feet(boxes, rays) == 1);
  const Obb grown = Obb::from_pose(boxes[1].pose, boxes[1].size);
  CHECK(grown.min_z() == Approx(0.0).margin(1e-9));
  CHECK(boxes[1].size.z() == Approx(lean.size.z()).margin(0.002));  // grown along its length
  CHECK(boxes[1].size.x() == Approx(lean.size.x()));
  CHECK((boxes[1].pose.t - lean.pose.translation()).norm() < 0.002);
  CHECK(boxes[0].pose.t == as_box(front).pose.t);  // the upright box as it was
  // Off: as it was.
  TiltedFootOptions off;
  off.enabled = false;
  std::vector<UprightBox> kept{as_box(front), upper_part(lean, 0.08)};
  CHECK(grow_tilted_feet(kept, rays, off) == 0);
}

TEST_CASE("tilted foot: a leaning box fitted into the box it leans on still reaches the table", "[perception][tilted]") {
  // The fit cuts 8 mm into the tall box behind it at its upper end (lean_seat.h mends that
  // later); only the part the box grows into must cut no box.
  const CastBox lean = leaning();
  const CastBox front = upright_box(0.0, -0.125, 0.0, Eigen::Vector3d(0.14, 0.06, 0.21));
  double back = -1.0;  // the leaning box's farthest reach in y
  for (int c = 0; c < 8; ++c)
    back = std::max(back, (lean.pose * Eigen::Vector3d((c & 1 ? 0.5 : -0.5) * lean.size.x(), (c & 2 ? 0.5 : -0.5) * lean.size.y(),
                                                       (c & 4 ? 0.5 : -0.5) * lean.size.z())).y());
  const CastBox behind = upright_box(0.0, back - 0.008 + 0.04, 0.0, Eigen::Vector3d(0.14, 0.08, 0.3));
  std::vector<UprightBox> boxes{as_box(front), as_box(behind), upper_part(lean, 0.08)};
  REQUIRE(ksmc::stdlib::tabletop::obb_sat(Obb::from_pose(boxes[2].pose, boxes[2].size),
                                          Obb::from_pose(boxes[1].pose, boxes[1].size))
              .depth > 0.005);
  CHECK(grow_tilted_feet(boxes, rays_of({front, behind, lean})) == 1);
  CHECK(Obb::from_pose(boxes[2].pose, boxes[2].size).min_z() == Approx(0.0).margin(1e-9));
  CHECK(boxes[2].size.z() == Approx(lean.size.z()).margin(0.002));
}

TEST_CASE("tilted foot: a box whose lower part was seen empty, or that would cut into a box, stays", "[perception][tilted]") {
  const CastBox lean = leaning();
  // Nothing in front: the rays pass where the lower part would be and end on the table.
  std::vector<UprightBox> seen_empty{upper_part(lean, 0.08)};
  CHECK(grow_tilted_feet(seen_empty, rays_of({}), TiltedFootOptions{}) == 0);
  CHECK(seen_empty[0].size.z() == Approx(0.08));
  // The box propped on a block under its lower end (the block hidden behind the box in front):
  // growing down would cut into the block.
  const CastBox front = upright_box(0.0, -0.125, 0.0, Eigen::Vector3d(0.14, 0.06, 0.21));
  const CastBox block = upright_box(0.0, 0.03, 0.0, Eigen::Vector3d(0.1, 0.06, 0.12));
  std::vector<UprightBox> propped{as_box(front), as_box(block), upper_part(lean, 0.08)};
  CHECK(grow_tilted_feet(propped, rays_of({front, block, lean})) == 0);
}
