// planar_faces: a face seen at a slant, sampled in rows farther apart than the growing
// radius, is one face when rows may be joined (FaceOptions::row_factor); a face cut in two by
// a seam is joined again (join_coplanar_faces).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "stdlib/tabletop/perception/planar_faces.h"
#include "stdlib/tabletop/perception/tilted_box.h"

using namespace ksmc::stdlib::tabletop::perception;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A 6 cm wide face turned 25 degrees about x, seen at a growing slant: rows across its width,
// 6 mm apart over its near 5 cm, then `far_row` apart over 6 cm more; points 3 mm apart along
// each row, 0.3 mm of deterministic ripple off the plane.
Points rows_of_face(double far_row) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(25.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Points out;
  int k = 0;
  for (double v = -0.05; v <= 0.06 + 1e-12; v += v < 0.0 ? 0.006 : far_row)
    for (double u = -0.03; u <= 0.03 + 1e-12; u += 0.003, ++k)
      out.push_back(r * Eigen::Vector3d(u, v, 0.0003 * std::sin(1.7 * k)) + Eigen::Vector3d(0.0, 0.0, 0.1));
  return out;
}

}  // namespace

TEST_CASE("planar faces: rows of a face seen at a slant are one face with row_factor", "[perception][tilted]") {
  const Points pts = rows_of_face(0.011);  // 11 mm between the far rows: past the 8 mm growing radius
  FaceOptions o;
  REQUIRE(o.grow_radius < 0.011);
  const std::vector<Face> apart = planar_faces(pts, o);  // the near part; each far row alone is too small
  REQUIRE(!apart.empty());
  CHECK(apart.front().points.size() < pts.size() * 3 / 4);
  o.row_factor = 2.0;
  const std::vector<Face> joined = planar_faces(pts, o);
  REQUIRE(!joined.empty());
  CHECK(joined.front().points.size() >= pts.size() - 2);
  CHECK(std::abs(joined.front().normal.dot(Eigen::AngleAxisd(25.0 * kDeg, Eigen::Vector3d::UnitX()) *
                                           Eigen::Vector3d::UnitZ())) > std::cos(2.0 * kDeg));
  // The tilted fit joins rows; the faces of an upright box's wall test (box_fit) do not.
  CHECK(TiltOptions{}.faces.row_factor > 1.0);
  CHECK(FaceOptions{}.row_factor <= 1.0);
}

TEST_CASE("planar faces: a parallel face a row's width away on another plane is not joined", "[perception][tilted]") {
  // The same face twice, side by side 7.5 cm apart and 1 cm apart in height: a step, not
  // rows of one face.
  Points pts = rows_of_face(0.011);
  const std::size_t first = pts.size();
  for (const Eigen::Vector3d& p : rows_of_face(0.011)) pts.push_back(p + Eigen::Vector3d(0.075, 0.0, 0.01));
  FaceOptions o;
  o.row_factor = 2.0;
  const std::vector<Face> faces = planar_faces(pts, o);
  for (const Face& f : faces) {
    const bool a = f.points.front() < static_cast<int>(first), b = f.points.back() >= static_cast<int>(first);
    CHECK(!(a && b));  // no face holds points of both
  }
}

TEST_CASE("planar faces: a face cut in two by a seam is joined, a parallel face off its plane is not",
          "[perception][tilted]") {
  // A 6 x 11 cm face turned 25 degrees about x, rows 4 mm apart but 12 mm apart across its
  // middle (an occluder's edge): two faces. A third beside it, parallel, 6 mm off its plane.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(25.0 * kDeg, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Points pts;
  int k = 0;
  for (double v = -0.05; v <= 0.06 + 1e-12; v += 0.004) {
    if (std::abs(v) < 0.004) continue;  // rows at -6 and +6 mm either side
    for (double u = -0.03; u <= 0.03 + 1e-12; u += 0.003, ++k)
      pts.push_back(r * Eigen::Vector3d(u, v, 0.0003 * std::sin(1.7 * k)) + Eigen::Vector3d(0.0, 0.0, 0.1));
  }
  const std::size_t split = pts.size();
  for (double v = -0.05; v <= 0.06 + 1e-12; v += 0.004)
    for (double u = 0.045; u <= 0.08 + 1e-12; u += 0.003, ++k)
      pts.push_back(r * Eigen::Vector3d(u, v, 0.006 + 0.0003 * std::sin(1.7 * k)) + Eigen::Vector3d(0.0, 0.0, 0.1));
  FaceOptions o;
  o.row_factor = 2.0;
  std::vector<Face> faces = planar_faces(pts, o);
  REQUIRE(faces.size() == 3);
  std::vector<Face> kept = faces;
  join_coplanar_faces(pts, kept, o, [](const Face&) { return false; });
  CHECK(kept.size() == 3);
  join_coplanar_faces(pts, faces, o, [](const Face&) { return true; });
  REQUIRE(faces.size() == 2);
  CHECK(faces[0].points.size() == split);  // the two halves, largest first
  CHECK(std::is_sorted(faces[0].points.begin(), faces[0].points.end()));
  CHECK(faces[1].points.front() >= static_cast<int>(split));  // the face off the plane stays apart
  CHECK(std::abs(faces[0].normal.dot(r.col(2))) > std::cos(1.0 * kDeg));
}
