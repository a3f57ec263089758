// Tilted boxes get a full 3D box; upright boxes (any yaw, square footprints included) keep
// the upright fit; a box leaning on an upright one comes out as two boxes.
#include <catch2/catch.hpp>

#include <cmath>

#include "stdlib/tabletop/perception/box_compare.h"
#include "stdlib/tabletop/perception/cluster_boxes.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::tests::perception::add_visible_box;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const Eigen::Vector3d kSensor(0.1, -0.7, 0.8);

Eigen::Isometry3d posed(double yaw, double tilt, const Eigen::Vector3d& t) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  p.translation() = t;
  return p;
}

// A box turned by `tilt` about its x axis and `yaw` about the vertical, its lowest corner
// on the table (z = 0) at (0, y).
Eigen::Isometry3d resting(double yaw, double tilt, const Eigen::Vector3d& size, double y = 0.0) {
  Eigen::Isometry3d p = posed(yaw, tilt, Eigen::Vector3d::Zero());
  double low = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner((c & 1 ? 0.5 : -0.5) * size.x(), (c & 2 ? 0.5 : -0.5) * size.y(), (c & 4 ? 0.5 : -0.5) * size.z());
    low = std::min(low, (p.linear() * corner).z());
  }
  p.translation() = Eigen::Vector3d(0.0, y, -low);
  return p;
}

BoxError error_of(const UprightBox& b, const Eigen::Isometry3d& truth, const Eigen::Vector3d& size) {
  return compare_boxes(b.pose.t, b.pose.rotation(), b.size, truth.translation(), truth.linear(), size);
}

}  // namespace

TEST_CASE("tilted box: a leaning box gets its 3D orientation and sizes", "[perception][tilted]") {
  for (double tilt : {10.0, 25.0, 40.0}) {
    for (double yaw : {0.0, 0.7, 1.9}) {
      const Eigen::Vector3d size(0.16, 0.10, 0.05);
      const Eigen::Isometry3d truth = resting(yaw, tilt * kDeg, size);
      Points pts;
      add_visible_box(pts, truth, size, 0.003, kSensor, 0.0005);
      const auto boxes = fit_cluster_boxes(pts);
      INFO("tilt " << tilt << " yaw " << yaw);
      REQUIRE(boxes.size() == 1);
      const BoxError e = error_of(boxes[0], truth, size);
      CHECK(e.centre < 0.004);
      CHECK(e.angle < 1.5 * kDeg);
      CHECK(e.max_size() < 0.005);
      // Canonical: axis 2 is the one nearest the table normal, pointing up.
      CHECK(boxes[0].pose.rotation()(2, 2) > std::cos(45.0 * kDeg));
    }
  }
}

TEST_CASE("tilted box: a leaning box seen by one face only is grown down to the table", "[perception][tilted]") {
  const Eigen::Vector3d size(0.16, 0.10, 0.05);
  const Eigen::Isometry3d truth = resting(0.4, 25.0 * kDeg, size);
  Points all, face;
  add_visible_box(all, truth, size, 0.003, kSensor, 0.0005);
  const Eigen::Vector3d n = truth.linear().col(2);  // the large face turned up
  for (const auto& p : all)
    if (std::abs((p - truth.translation()).dot(n) - 0.5 * size.z()) < 0.002) face.push_back(p);
  const auto boxes = fit_cluster_boxes(face);
  REQUIRE(boxes.size() == 1);
  const BoxError e = error_of(boxes[0], truth, size);
  CHECK(e.angle < 1.5 * kDeg);
  CHECK(e.max_size() < 0.005);  // the 5 cm thickness: no face shows it, the table does
  CHECK(e.centre < 0.004);
}

TEST_CASE("tilted box: upright boxes keep the upright fit, square footprints included", "[perception][tilted]") {
  for (const Eigen::Vector3d& size : {Eigen::Vector3d(0.07, 0.07, 0.19), Eigen::Vector3d(0.10, 0.10, 0.04),
                                     Eigen::Vector3d(0.20, 0.06, 0.05)}) {
    for (double yaw = 0.0; yaw < 90.0; yaw += 15.0) {
      const Eigen::Isometry3d truth = posed(yaw * kDeg, 0.0, Eigen::Vector3d(0.0, 0.0, 0.5 * size.z()));
      Points pts;
      add_visible_box(pts, truth, size, 0.003, kSensor, 0.0005);
      const auto boxes = fit_cluster_boxes(pts);
      INFO("size " << size.transpose() << " yaw " << yaw);
      REQUIRE(boxes.size() == 1);
      CHECK(boxes[0].pose.rotation()(2, 2) > std::cos(1e-6));  // exactly upright: the upright fit
      CHECK(error_of(boxes[0], truth, size).max_size() < 0.005);
    }
  }
}

TEST_CASE("tilted box: a box leaning on an upright box is one cluster and two boxes", "[perception][tilted]") {
  const Eigen::Vector3d upright_size(0.10, 0.08, 0.18), leaning_size(0.15, 0.12, 0.04);
  const Eigen::Isometry3d upright = posed(0.0, 0.0, Eigen::Vector3d(0.0, 0.0, 0.09));
  // Leaning on the upright box's -y face, turned 60 degrees about the x axis, its lowest
  // edge on the table.
  const double tilt = 60.0 * kDeg;
  const Eigen::Matrix3d r = Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d half = 0.5 * leaning_size;
  // Lowest corner of the rotated box at z = 0, its top edge against the face y = -0.04.
  double low = 0.0, back = -1.0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner = r * Eigen::Vector3d((c & 1 ? 1 : -1) * half.x(), (c & 2 ? 1 : -1) * half.y(),
                                                       (c & 4 ? 1 : -1) * half.z());
    low = std::min(low, corner.z());
    back = std::max(back, corner.y());
  }
  Eigen::Isometry3d leaning = Eigen::Isometry3d::Identity();
  leaning.linear() = r;
  leaning.translation() = Eigen::Vector3d(0.0, -0.04 - back, -low);
  Points pts;
  add_visible_box(pts, upright, upright_size, 0.003, kSensor, 0.0005, 1);
  add_visible_box(pts, leaning, leaning_size, 0.003, kSensor, 0.0005, 2);
  const auto boxes = fit_cluster_boxes(pts);
  REQUIRE(boxes.size() == 2);
  const UprightBox& t = boxes[0];
  const UprightBox& u = boxes[1];
  const BoxError et = error_of(t, leaning, leaning_size), eu = error_of(u, upright, upright_size);
  CHECK(et.centre < 0.005);
  CHECK(et.angle < 1.5 * kDeg);
  CHECK(et.max_size() < 0.006);
  CHECK(eu.centre < 0.01);
  CHECK(eu.angle < 1.0 * kDeg);
}
