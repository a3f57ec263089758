// lean_seat: a tilted box cutting into the upright box it leans on is cut back on a face the
// sensor did not see, its foot kept where it stood.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/obb_sat.h"
#include "stdlib/tabletop/perception/lean_seat.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::Obb;
using ksmc::stdlib::tabletop::obb_sat;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A 10 x 10 x 20 cm box standing on the table, its -x face at x = 0.1.
UprightBox wall() {
  UprightBox b;
  b.size = Eigen::Vector3d(0.1, 0.1, 0.2);
  b.pose.t = Eigen::Vector3d(0.15, 0.0, 0.1);
  return b;
}

// A board `thick` thick (x), 10 cm wide (y), 20 cm long (z), turned 20 degrees about y (its top
// towards the wall), its lowest edge on the table at x = foot.
UprightBox board(double thick, double foot) {
  const double a = 20.0 * kDeg;
  UprightBox b;
  b.size = Eigen::Vector3d(thick, 0.1, 0.2);
  b.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()));
  const Eigen::Matrix3d r = b.pose.q.toRotationMatrix();
  // The lowest vertex is the one at (+x, -z) in the board's frame.
  const Eigen::Vector3d low = r * Eigen::Vector3d(0.5 * thick, 0.0, -0.1);
  b.pose.t = Eigen::Vector3d(foot, 0.0, 0.0) - low;
  return b;
}

double depth(const UprightBox& a, const UprightBox& b) {
  const auto r = obb_sat(Obb::from_pose(a.pose, a.size), Obb::from_pose(b.pose, b.size));
  return r.overlapping ? r.depth : 0.0;
}

// Points on the faces of `b` the sensor sees from in front of the board (-x): its face away
// from the wall (local -x) and its top end (local +z), 5 mm apart.
Points seen_faces(const UprightBox& b) {
  const Obb o = Obb::from_pose(b.pose, b.size);
  Points out;
  for (double v = -0.045; v <= 0.045; v += 0.005) {
    for (double w = -0.095; w <= 0.095; w += 0.005)
      out.push_back(o.center + o.axes * Eigen::Vector3d(-o.half.x(), v, w));
    for (double u = -0.8; u <= 0.8; u += 0.4)
      out.push_back(o.center + o.axes * Eigen::Vector3d(u * o.half.x(), v, o.half.z()));
  }
  return out;
}

}  // namespace

TEST_CASE("lean seat: a board fitted too thick is cut back on its unseen face", "[perception][lean_seat]") {
  // The true board is 2 cm thick and touches the wall; its fit is 3.5 cm thick, the extra on
  // the side the sensor did not see (towards the wall), so it cuts into the wall.
  const UprightBox truth = board(0.02, 0.1 - 0.2 * std::sin(20.0 * kDeg));
  REQUIRE(depth(truth, wall()) < 1e-6);
  const Obb t = Obb::from_pose(truth.pose, truth.size);
  UprightBox fit = truth;  // its -x face kept, 1.5 cm added on its +x side, its foot set on the table
  fit.size.x() = 0.035;
  fit.pose.t += 0.5 * 0.015 * t.axes.col(0);
  fit.pose.t.z() -= Obb::from_pose(fit.pose, fit.size).min_z();
  REQUIRE(depth(fit, wall()) > 0.005);
  std::vector<UprightBox> boxes{wall(), fit};
  const std::vector<Points> own{{}, seen_faces(truth)};
  CHECK(seat_leaning_boxes(boxes, own) == 1);
  CHECK(depth(boxes[1], boxes[0]) <= 0.001 + 1e-9);
  CHECK(boxes[1].size.x() == Approx(0.02).margin(0.0015));  // cut on its unseen face
  CHECK(boxes[1].size.y() == Approx(0.1));
  CHECK(boxes[1].size.z() == Approx(0.2));
  const Obb after = Obb::from_pose(boxes[1].pose, boxes[1].size);
  CHECK(after.min_z() == Approx(0.0).margin(1e-9));  // its foot stays on the table
  // Its seen face stays within a few mm of where the sensor saw it.
  const Eigen::Vector3d seen_face = after.center - after.half.x() * after.axes.col(0);
  CHECK((seen_face - (t.center - t.half.x() * t.axes.col(0))).norm() < 0.002);
  CHECK(boxes[0].pose.t == wall().pose.t);  // the upright box as it was
}

TEST_CASE("lean seat: boxes left as they are", "[perception][lean_seat]") {
  const UprightBox truth = board(0.02, 0.1 - 0.2 * std::sin(20.0 * kDeg));
  const Obb t = Obb::from_pose(truth.pose, truth.size);
  UprightBox fit = truth;
  fit.size.x() = 0.035;
  fit.pose.t += 0.5 * 0.015 * t.axes.col(0);
  fit.pose.t.z() -= Obb::from_pose(fit.pose, fit.size).min_z();
  // Its face towards the wall seen too (points on its lower part, clear of the wall): no face
  // the sensor did not see can be cut back to clear the wall, and the box is left as it was.
  Points all = seen_faces(fit);
  const Obb f = Obb::from_pose(fit.pose, fit.size);
  for (double v = -0.04; v <= 0.04; v += 0.01)
    for (double w = -0.09; w <= 0.0; w += 0.01) all.push_back(f.center + f.axes * Eigen::Vector3d(f.half.x(), v, w));
  std::vector<UprightBox> seen{wall(), fit};
  CHECK(seat_leaning_boxes(seen, {{}, all}) == 0);
  CHECK(seen[1].size.x() == Approx(0.035));
  CHECK(seen[1].pose.t == fit.pose.t);
  // Touching, not cutting in: nothing to do.
  std::vector<UprightBox> touching{wall(), truth};
  CHECK(seat_leaning_boxes(touching, {{}, seen_faces(truth)}) == 0);
  // Upright boxes overlapping each other are not this pass's.
  UprightBox other = wall();
  other.pose.t.x() -= 0.02;
  std::vector<UprightBox> two{wall(), other};
  CHECK(seat_leaning_boxes(two, {{}, {}}) == 0);
  // Off: as it was.
  LeanSeatOptions off;
  off.enabled = false;
  std::vector<UprightBox> kept{wall(), fit};
  CHECK(seat_leaning_boxes(kept, {{}, seen_faces(truth)}, off) == 0);
}

TEST_CASE("lean seat: a box lying across a low box, fitted too thick underneath, is cut there and not lowered",
          "[perception][lean_seat]") {
  // A 20 x 7 x 4.8 cm box turned 20 degrees about y, its foot on the table at x = 0.2, lying
  // across a bar (4 cm deep in x, 20 cm long in y) whose top edge touches its underside. The
  // sensor saw its top and its upper end; the fit put 8 mm too much on its underside, so it
  // cuts into the bar. Lowering the box after cutting its underside would press that side
  // back into the bar (a 27 mm cut on the simulated cloud this case came from).
  const double a = 20.0 * kDeg, thick = 0.048;
  UprightBox truth;
  truth.size = Eigen::Vector3d(0.2, 0.07, thick);
  truth.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()));
  const Eigen::Matrix3d r = truth.pose.q.toRotationMatrix();
  truth.pose.t = Eigen::Vector3d(0.2, 0.0, 0.0) - r * Eigen::Vector3d(0.1, 0.0, -0.5 * thick);
  // The bar's height: the underside's height over the bar's edge nearer the foot.
  const Eigen::Vector3d under = truth.pose.t - 0.5 * thick * r.col(2), up = r.col(2);
  const double bar_x = 0.05, edge = bar_x + 0.02;
  const double h = under.z() - up.x() * (edge - under.x()) / up.z();
  UprightBox bar;
  bar.size = Eigen::Vector3d(0.04, 0.2, h);
  bar.pose.t = Eigen::Vector3d(bar_x, 0.0, 0.5 * h);
  REQUIRE(depth(truth, bar) < 1e-6);
  UprightBox fit = truth;  // 8 mm more on the underside (local -z)
  fit.size.z() += 0.008;
  fit.pose.t -= 0.004 * r.col(2);
  REQUIRE(depth(fit, bar) > 0.005);
  // The points the sensor saw: the top (local +z) and the upper end (local -x), 5 mm apart.
  const Obb t = Obb::from_pose(truth.pose, truth.size);
  Points seen;
  for (double v = -0.03; v <= 0.03; v += 0.005) {
    for (double u = -0.095; u <= 0.095; u += 0.005) seen.push_back(t.center + t.axes * Eigen::Vector3d(u, v, t.half.z()));
    for (double w = -0.02; w <= 0.02; w += 0.005) seen.push_back(t.center + t.axes * Eigen::Vector3d(-t.half.x(), v, w));
  }
  std::vector<UprightBox> boxes{bar, fit};
  CHECK(seat_leaning_boxes(boxes, {{}, seen}) == 1);
  CHECK(depth(boxes[1], boxes[0]) <= 0.001 + 1e-9);
  CHECK(boxes[1].size.z() == Approx(thick).margin(0.0015));  // the 8 mm cut off its underside
  CHECK(boxes[1].size.x() == Approx(0.2));
  const Obb after = Obb::from_pose(boxes[1].pose, boxes[1].size);
  const Eigen::Vector3d top = after.center + after.half.z() * after.axes.col(2);
  CHECK((top - (t.center + t.half.z() * t.axes.col(2))).norm() < 0.001);  // its top where the sensor saw it
}
