// overhang: a box resting on other boxes with its centre beyond their upward faces
// (stdlib/tabletop/extract_overhang.h), and the block domains/tabletop.ksm binds
// (blocks::obb::overhang: supporters are the touching bodies it is higher than; the table
// supports everywhere).
#include <catch2/catch.hpp>

#include <vector>

#include "stdlib/tabletop/block_scene.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/extract_overhang.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::box;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

// A 10 cm cube on the table, and a 6 cm cube resting on it with its centre at x = dx.
const Obb kLower = box(Vector3d(0.0, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1));
Obb upper_at(double dx, double dy = 0.0) { return box(Vector3d(dx, dy, 0.13), Vector3d(0.06, 0.06, 0.06)); }

}  // namespace

TEST_CASE("overhang: centre over the supporter's top face or beyond it", "[geometry]") {
  const std::vector<Obb> on{kLower};
  CHECK(support_overhang(upper_at(0.0), on) == 0.0);
  CHECK(support_overhang(upper_at(0.049), on) == 0.0);  // over the face, near its edge
  CHECK(support_overhang(upper_at(0.08), on) == Approx(0.03));
  CHECK(support_overhang(upper_at(0.08, 0.09), on) == Approx(std::hypot(0.03, 0.04)));  // beyond a corner
  CHECK(extract_overhang(upper_at(0.08), on, 0.005));
  CHECK_FALSE(extract_overhang(upper_at(0.08), on, 0.05));
  CHECK_FALSE(extract_overhang(upper_at(0.052), on, 0.005));  // within the margin
  CHECK(support_overhang(upper_at(0.3), {}) == 0.0);  // nothing under it: not this evidence
}

TEST_CASE("overhang: a box bridging two supporters rests over the hull of their faces", "[geometry]") {
  const Obb left = box(Vector3d(-0.08, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1));
  const Obb right = box(Vector3d(0.08, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1));
  const Obb bridge = box(Vector3d(0.0, 0.0, 0.12), Vector3d(0.3, 0.08, 0.04));
  const std::vector<Obb> both{left, right};
  CHECK(support_overhang(bridge, both) == 0.0);  // over the 6 cm gap between them
  const std::vector<Obb> one{right};
  CHECK(support_overhang(bridge, one) == Approx(0.03));  // on the right one alone it would topple
}

TEST_CASE("overhang: the upward face of a turned supporter", "[geometry]") {
  // A 20 x 4 x 10 cm board turned 90 deg about x lies 4 cm high: its upward face is the one
  // of its local y axis, 20 x 10 cm on the table plane (not the 20 x 4 cm face of local z).
  const Obb board = box(Vector3d(0.0, 0.0, 0.02), Vector3d(0.2, 0.04, 0.1), rot(90.0, Vector3d::UnitX()));
  const std::vector<Obb> on{board};
  CHECK(support_overhang(box(Vector3d(0.0, 0.04, 0.07), Vector3d(0.06, 0.06, 0.06)), on) == 0.0);
  CHECK(support_overhang(box(Vector3d(0.0, 0.07, 0.07), Vector3d(0.06, 0.06, 0.06)), on) == Approx(0.02));
}

TEST_CASE("overhang block: supporters are the touching bodies under the box; the table supports everywhere",
          "[geometry]") {
  Scene input;
  input.objects.push_back(object("lower", Vector3d(0.0, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1)));
  input.objects.push_back(object("on_edge", Vector3d(0.08, 0.0, 0.13), Vector3d(0.06, 0.06, 0.06)));
  input.objects.push_back(object("centred", Vector3d(0.4, 0.0, 0.13), Vector3d(0.06, 0.06, 0.06)));
  input.objects.push_back(object("under", Vector3d(0.4, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1)));
  input.objects.push_back(object("far_off", Vector3d(0.0, 0.4, 0.03), Vector3d(0.06, 0.06, 0.06)));
  const blocks::Scene s(input);
  const double eps = 0.004, margin = 0.005;
  CHECK_FALSE(blocks::obb::overhang(s, 0, eps, margin));  // the table
  CHECK_FALSE(blocks::obb::overhang(s, 1, eps, margin));  // on the table
  CHECK(blocks::obb::overhang(s, 2, eps, margin));        // 3 cm beyond the lower cube
  CHECK_FALSE(blocks::obb::overhang(s, 3, eps, margin));  // centred on `under`
  CHECK_FALSE(blocks::obb::overhang(s, 5, eps, margin));  // on the table beside everything
  // Lifted 2 cm off the lower cube, it rests on nothing: hover's evidence, not overhang's.
  blocks::Scene lifted(input);
  Pose up = input.objects[1].pose;
  up.t.z() += 0.02;
  lifted.set_pose(2, up);
  CHECK_FALSE(blocks::obb::overhang(lifted, 2, eps, margin));
}
