// A thin box lying on a larger box's face is a strip of that face (face_strip.h); a thin box
// apart from it, one deep inside it, a thick box and a larger "strip" are not.
#include <catch2/catch.hpp>

#include "stdlib/tabletop/perception/face_strip.h"

using namespace ksmc::stdlib::tabletop::perception;

namespace {

UprightBox box_at(const Eigen::Vector3d& centre, const Eigen::Vector3d& size) {
  UprightBox b;
  b.pose.t = centre;
  b.size = size;
  return b;
}

// Points on the face y = y0 of a strip x in [x0, x1], z in [z0, z1], every 3 mm.
Points face_points(double y0, double x0, double x1, double z0, double z1) {
  Points out;
  for (double x = x0; x <= x1; x += 0.003)
    for (double z = z0; z <= z1; z += 0.003) out.emplace_back(x, y0, z);
  return out;
}

}  // namespace

TEST_CASE("face strip: a thin box on a larger box's face is part of it", "[perception][face_strip]") {
  const UprightBox outer = box_at({0.0, 0.0, 0.075}, {0.20, 0.10, 0.15});
  const Points strip = face_points(-0.05, 0.06, 0.10, 0.02, 0.12);  // on the front face
  const UprightBox thin = box_at({0.08, -0.05, 0.07}, {0.04, 0.005, 0.10});
  CHECK(is_face_strip(thin, strip, outer));

  const Points away = face_points(-0.09, 0.06, 0.10, 0.02, 0.12);  // 4 cm in front of it
  CHECK_FALSE(is_face_strip(box_at({0.08, -0.09, 0.07}, {0.04, 0.005, 0.10}), away, outer));

  const UprightBox thick = box_at({0.08, -0.03, 0.07}, {0.04, 0.04, 0.10});  // a box of its own
  CHECK_FALSE(is_face_strip(thick, strip, outer));

  CHECK_FALSE(is_face_strip(outer, strip, thin));  // the larger box is never the strip

  // A thin surface 3 cm inside the box (a multipath ghost behind a glossy face) is no strip.
  const Points ghost = face_points(-0.02, 0.06, 0.10, 0.02, 0.12);
  CHECK_FALSE(is_face_strip(box_at({0.08, -0.02, 0.07}, {0.04, 0.005, 0.10}), ghost, outer));
  FaceStripOptions off;
  off.thin = -1.0;
  CHECK_FALSE(is_face_strip(thin, strip, outer, off));
}
