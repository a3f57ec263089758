// OBB geometry and the evidence extractors on the configurations of seed Fig. 4.9–4.11.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "stdlib/tabletop/extract_contact.h"
#include "stdlib/tabletop/extract_higher.h"
#include "stdlib/tabletop/extract_intersect.h"
#include "stdlib/tabletop/extract_overlap.h"
#include "stdlib/tabletop/extract_stable.h"
#include "stdlib/tabletop/obb_distance.h"
#include "stdlib/tabletop/obb_sat.h"
#include "stdlib/tabletop/pair_geometry.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::box;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

const Obb kTable = TableSlab{}.obb();
const EvidenceParams kParams{};

// A 10 cm cube standing on the table, bottom face at z = gap.
Obb cube_on_table(double gap = 0.0, const Vector3d& xy = Vector3d::Zero()) {
  return box(Vector3d(xy.x(), xy.y(), 0.05 + gap), Vector3d(0.1, 0.1, 0.1));
}

}  // namespace

TEST_CASE("face contact: a box standing on the table", "[geometry]") {
  const Obb b = cube_on_table();
  CHECK(obb_closest_points(b, kTable).distance == Approx(0.0).margin(1e-12));
  CHECK(extract_contact(b, kTable, kParams));
  CHECK_FALSE(extract_intersect(b, kTable, kParams));
  CHECK(extract_stable(b, kParams));
  CHECK(extract_higher(b, kTable, kParams));
  CHECK_FALSE(extract_higher(kTable, b, kParams));
  // 1 cm above the table: within the vertical tolerance; 3 cm above: not.
  CHECK(extract_contact(cube_on_table(0.01), kTable, kParams));
  CHECK_FALSE(extract_contact(cube_on_table(0.03), kTable, kParams));
  CHECK(obb_closest_points(cube_on_table(0.03), kTable).distance == Approx(0.03).epsilon(1e-9));
  // Sunk 1 cm into the table (noise): still contact; sunk 3 cm: intersect.
  CHECK(extract_contact(cube_on_table(-0.01), kTable, kParams));
  CHECK(extract_intersect(cube_on_table(-0.03), kTable, kParams));
  CHECK_FALSE(extract_contact(cube_on_table(-0.03), kTable, kParams));
}

TEST_CASE("vertex contact: a cube balanced on a corner above another", "[geometry]") {
  const Obb lower = cube_on_table();
  // Rotate so the body diagonal (1,1,1) points along -z: vertex 0 (-,-,-)... is lowest.
  const Eigen::Matrix3d r = Eigen::Quaterniond::FromTwoVectors(Vector3d(1, 1, 1).normalized(), Vector3d(0, 0, 1))
                                .toRotationMatrix();
  Obb upper = box(Vector3d::Zero(), Vector3d(0.1, 0.1, 0.1), r);
  const double gap = 0.002;
  upper.center = Vector3d(0.0, 0.0, 0.1 + gap - upper.min_z());
  CHECK(upper.min_z() == Approx(0.1 + gap));
  const ClosestPoints cp = obb_closest_points(upper, lower);
  CHECK(cp.distance == Approx(gap).epsilon(1e-9));
  CHECK((cp.on_a - Vector3d(0, 0, 0.1 + gap)).norm() < 1e-9);  // the vertex itself
  CHECK(extract_contact(upper, lower, kParams));
  CHECK_FALSE(extract_intersect(upper, lower, kParams));
  CHECK_FALSE(extract_stable(upper, kParams));
  CHECK(extract_higher(upper, lower, kParams));
}

TEST_CASE("edge contact: a box resting on an edge, and crossing edges", "[geometry]") {
  const Obb lower = cube_on_table();
  Obb upper = box(Vector3d::Zero(), Vector3d(0.1, 0.06, 0.06), rot(45, Vector3d::UnitX()));
  upper.center.z() = 0.1 + 0.001 - upper.min_z();
  CHECK(obb_closest_points(upper, lower).distance == Approx(0.001).epsilon(1e-9));
  CHECK(extract_contact(upper, lower, kParams));
  CHECK_FALSE(extract_intersect(upper, lower, kParams));

  // Two roof-shaped boxes whose ridge edges cross at right angles, 3 mm apart
  // horizontally offset so the closest feature pair is edge–edge.
  const Obb a = box(Vector3d(0, 0, 0), Vector3d(0.2, 0.05, 0.05), rot(45, Vector3d::UnitX()));
  const double ra = 0.05 / std::sqrt(2.0);  // ridge height above centre
  const Obb b = box(Vector3d(0, 0, 2 * ra + 0.003), Vector3d(0.05, 0.2, 0.05), rot(45, Vector3d::UnitY()));
  const ClosestPoints cp = obb_closest_points(a, b);
  CHECK(cp.distance == Approx(0.003).epsilon(1e-9));
  CHECK((cp.on_a - Vector3d(0, 0, ra)).norm() < 1e-9);
  CHECK((cp.on_b - Vector3d(0, 0, ra + 0.003)).norm() < 1e-9);
  // SAT alone only gives a lower bound of this distance; the exact value is what contact uses.
  CHECK(obb_sat(a, b).gap <= cp.distance + 1e-12);
}

TEST_CASE("containment is intersection, whatever the depth", "[geometry]") {
  const Obb big = box(Vector3d(0, 0, 0.1), Vector3d(0.2, 0.2, 0.2));
  const Obb small = box(Vector3d(0.01, 0, 0.1), Vector3d(0.05, 0.05, 0.05), rot(30, Vector3d(1, 2, 3)));
  const Obb tiny = box(Vector3d(0.0, 0.05, 0.1), Vector3d(0.002, 0.002, 0.002));
  CHECK(extract_intersect(small, big, kParams));
  CHECK(extract_intersect(big, small, kParams));
  CHECK_FALSE(extract_contact(small, big, kParams));
  CHECK(extract_intersect(tiny, big, kParams));
  CHECK_FALSE(extract_contact(tiny, big, kParams));
  CHECK(obb_closest_points(small, big).distance == 0.0);
}

TEST_CASE("lean: a box leaning against a standing box", "[geometry]") {
  const Obb standing = box(Vector3d(0, 0, 0.1), Vector3d(0.1, 0.1, 0.2));
  // A 0.2 m tall board tilted 20° about y towards +x, touching standing's -x face.
  const Eigen::Matrix3d r = rot(20, Vector3d::UnitY());
  Obb board = box(Vector3d::Zero(), Vector3d(0.02, 0.1, 0.2), r);
  board.center.z() = -board.min_z();  // lowest edge on the table
  // Top of the board: max x over the vertices must touch x = -0.05.
  double max_x = -1e9;
  for (const auto& v : board.vertices()) max_x = std::max(max_x, v.x());
  board.center.x() = -0.05 - max_x;
  CHECK_FALSE(extract_stable(board, kParams));
  CHECK(tilt_angle(board) == Approx(20.0 * 3.14159265358979323846 / 180.0));
  CHECK(extract_contact(board, standing, kParams));
  CHECK_FALSE(extract_intersect(board, standing, kParams));
  CHECK(extract_contact(board, kTable, kParams));
  CHECK_FALSE(extract_higher(board, standing, kParams));
  CHECK_FALSE(extract_higher(standing, board, kParams));
}

TEST_CASE("hover: a box floating above the table touches nothing", "[geometry]") {
  const Obb b = cube_on_table(0.08);
  CHECK_FALSE(extract_contact(b, kTable, kParams));
  CHECK_FALSE(extract_intersect(b, kTable, kParams));
  CHECK(extract_stable(b, kParams));
  CHECK(extract_higher(b, kTable, kParams));
}

TEST_CASE("stacked: support relations up a stack", "[geometry]") {
  const Obb bottom = box(Vector3d(0, 0, 0.02), Vector3d(0.2, 0.15, 0.04));
  const Obb top = box(Vector3d(0.01, -0.01, 0.04 + 0.03 + 0.004), Vector3d(0.1, 0.1, 0.06), rot(4, Vector3d::UnitZ()));
  CHECK(extract_stable(top, kParams));
  CHECK(extract_contact(top, bottom, kParams));
  CHECK_FALSE(extract_intersect(top, bottom, kParams));
  CHECK(extract_higher(top, bottom, kParams));
  CHECK_FALSE(extract_higher(bottom, top, kParams));
  CHECK(extract_higher(top, kTable, kParams));
  CHECK_FALSE(extract_contact(top, kTable, kParams));
}

TEST_CASE("stacked and tilted within the stable tolerance: still higher", "[geometry]") {
  // A 30 cm wide box resting on a 30 x 30 x 10 cm box, tilted 8 deg about x: its bottom
  // face centre touches the lower top face (z = 0.1), its lowest corner is 2 cm below it.
  const Obb lower = box(Vector3d(0, 0, 0.05), Vector3d(0.3, 0.3, 0.1));
  const double tilt = 8.0 * 3.14159265358979323846 / 180.0;
  const Obb upper = box(Vector3d(0, 0, 0.1 + 0.05 * std::cos(tilt)), Vector3d(0.3, 0.3, 0.1), rot(8, Vector3d::UnitX()));
  CHECK(extract_stable(upper, kParams));
  REQUIRE(upper.min_z() < lower.max_z() - kParams.higher_tol);  // a vertex test would fail
  CHECK(face_half_height(upper) == Approx(0.05 * std::cos(tilt)));
  CHECK(extract_higher(upper, lower, kParams));
  CHECK_FALSE(extract_higher(lower, upper, kParams));
  // Sunk into the lower box by more than the tolerance: no longer higher.
  const Obb sunk = box(Vector3d(0, 0, 0.1 + 0.05 * std::cos(tilt) - 0.016), Vector3d(0.3, 0.3, 0.1),
                       rot(8, Vector3d::UnitX()));
  CHECK_FALSE(extract_higher(sunk, lower, kParams));
}

TEST_CASE("flat boxes side by side: exactly parallel edges", "[geometry]") {
  const Vector3d size(0.12, 0.16, 0.04);
  const Obb a = box(Vector3d(0, 0, 0.02), size);
  for (double gap : {0.0, 0.001, 0.003}) {
    const Obb b = box(Vector3d(0.12 + gap, 0.03, 0.02), size);
    const SatResult sat = obb_sat(a, b);
    CHECK(std::isfinite(sat.depth));
    CHECK(std::isfinite(sat.gap));
    CHECK(obb_closest_points(a, b).distance == Approx(gap).margin(1e-12));
    CHECK(extract_contact(a, b, kParams));
    CHECK_FALSE(extract_intersect(a, b, kParams));
    CHECK_FALSE(extract_higher(a, b, kParams));
    CHECK_FALSE(extract_higher(b, a, kParams));
  }
  // Lateral 6 mm gap: no contact (the lateral tolerance is 4 mm).
  CHECK_FALSE(extract_contact(a, box(Vector3d(0.126, 0, 0.02), size), kParams));
  // Lateral overlap of 2 cm: intersection.
  const Obb c = box(Vector3d(0.10, 0, 0.02), size);
  CHECK(obb_sat(a, c).depth == Approx(0.02));
  CHECK(extract_intersect(a, c, kParams));
  CHECK_FALSE(extract_contact(a, c, kParams));
  // Same boxes, both rotated by the same yaw: cross axes stay degenerate.
  const Eigen::Matrix3d yaw = rot(33, Vector3d::UnitZ());
  const Obb ra = box(Vector3d(0, 0, 0.02), size, yaw);
  const Obb rb = box(yaw * Vector3d(0.121, 0, 0) + Vector3d(0, 0, 0.02), size, yaw);
  CHECK(obb_closest_points(ra, rb).distance == Approx(0.001).epsilon(1e-6));
  CHECK(extract_contact(ra, rb, kParams));
}

TEST_CASE("stable tolerance: tilt around the threshold", "[geometry]") {
  CHECK(extract_stable(box(Vector3d::Zero(), Vector3d(0.1, 0.1, 0.1), rot(7, Vector3d(1, 1, 0))), kParams));
  CHECK_FALSE(extract_stable(box(Vector3d::Zero(), Vector3d(0.1, 0.1, 0.1), rot(15, Vector3d(1, 1, 0))), kParams));
  // Lying on its side (90° about x) is stable: another edge is vertical.
  CHECK(extract_stable(box(Vector3d::Zero(), Vector3d(0.1, 0.2, 0.05), rot(90, Vector3d::UnitX())), kParams));
  EvidenceParams strict;
  strict.stable_tol_rad = 3.0 * 3.14159265358979323846 / 180.0;
  CHECK_FALSE(extract_stable(box(Vector3d::Zero(), Vector3d(0.1, 0.1, 0.1), rot(7, Vector3d(1, 1, 0))), strict));
}

TEST_CASE("random poses: exact distance vs brute-force sampled distance", "[geometry][property]") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> s(0.02, 0.2);
  auto random_box = [&] {
    const Vector3d axis(u(rng), u(rng), u(rng));
    return box(Vector3d(0.25 * u(rng), 0.25 * u(rng), 0.25 * u(rng)), Vector3d(s(rng), s(rng), s(rng)),
               rot(180.0 * u(rng), axis.norm() > 1e-3 ? axis : Vector3d::UnitZ()));
  };
  // Sampled distance: surface grid of `a` (spacing ≤ h), exact point-to-box distance to `b`.
  auto sampled = [](const Obb& a, const Obb& b, int n, double& spacing) {
    double best = 1e9;
    spacing = 0.0;
    for (int f = 0; f < 3; ++f) {
      const int g = (f + 1) % 3, k = (f + 2) % 3;
      spacing = std::max(spacing, std::hypot(2 * a.half[g] / n, 2 * a.half[k] / n));
      for (int sign : {-1, 1})
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j) {
            Vector3d l;
            l[f] = sign * a.half[f];
            l[g] = -a.half[g] + 2 * a.half[g] * i / n;
            l[k] = -a.half[k] + 2 * a.half[k] * j / n;
            best = std::min(best, b.distance_to(a.center + a.axes * l));
          }
    }
    return best;
  };
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Obb a = random_box();
    const Obb b = random_box();
    const ClosestPoints cp = obb_closest_points(a, b);
    const SatResult sat = obb_sat(a, b);
    REQUIRE(cp.overlapping == sat.overlapping);
    if (cp.overlapping) {
      // Some point of one box lies inside the other or the surfaces cross: sampled ≈ 0.
      continue;
    }
    ++separated;
    double h1 = 0.0, h2 = 0.0;
    const double brute = std::min(sampled(a, b, 40, h1), sampled(b, a, 40, h2));
    INFO("trial " << trial << " exact " << cp.distance << " sampled " << brute);
    CHECK(cp.distance <= brute + 1e-12);                           // exact is a true minimum
    CHECK(brute - cp.distance <= 0.5 * std::max(h1, h2) + 1e-12);  // and is attained
    CHECK((cp.on_a - cp.on_b).norm() == Approx(cp.distance).margin(1e-12));
    CHECK(a.distance_to(cp.on_a) < 1e-9);
    CHECK(b.distance_to(cp.on_b) < 1e-9);
    CHECK(sat.gap <= cp.distance + 1e-12);  // SAT is only a lower bound
  }
  CHECK(separated > 100);
}

TEST_CASE("pair geometry skips the exact distance only beyond the contact tolerances", "[geometry]") {
  const Obb a = box(Vector3d(0, 0, 0.05), Vector3d(0.1, 0.1, 0.1));
  const Obb far = box(Vector3d(0.3, 0.05, 0.05), Vector3d(0.1, 0.1, 0.1), rot(20, Vector3d::UnitZ()));
  const Obb near = box(Vector3d(0.113, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1), rot(3, Vector3d::UnitZ()));
  const double tol = kParams.max_contact_eps();
  const PairGeometry gf = pair_geometry(a, far, tol);
  CHECK_FALSE(gf.distance_exact);
  CHECK(gf.distance > tol);
  CHECK(gf.distance <= obb_closest_points(a, far).distance + 1e-12);
  const PairGeometry gn = pair_geometry(a, near, tol);
  CHECK(gn.distance_exact);
  CHECK(gn.distance == Approx(obb_closest_points(a, near).distance));
  CHECK(pair_geometry(a, far).distance_exact);  // no cut-off: always exact
}

TEST_CASE("vertical tolerances apply to stacking only, not to a thin box pushed in sideways", "[geometry]") {
  const Obb big = box(Vector3d(0, 0, 0.1), Vector3d(0.2, 0.2, 0.2));
  // 1 cm thin plate driven 5 cm into big's side just below its top face (plate z from
  // 0.189 to 0.199): the minimum-overlap axis is vertical (11 mm to push it out upwards,
  // below the 15 mm vertical tolerance) but this is no stack.
  const Obb plate = box(Vector3d(0.1 + 0.1 - 0.05, 0, 0.194), Vector3d(0.2, 0.1, 0.01));
  const PairGeometry g = pair_geometry(plate, big);
  CHECK(g.overlapping);
  CHECK(std::abs(g.direction.z()) == Approx(1.0));
  CHECK(g.depth == Approx(0.011));
  CHECK_FALSE(g.stacked);
  CHECK(extract_intersect(plate, big, kParams));
  CHECK_FALSE(extract_contact(plate, big, kParams));
  // The same plate 1 cm above a low box's top surface: stacked, within the vertical tolerance.
  const Obb low = box(Vector3d(0, 0, 0.02), Vector3d(0.2, 0.2, 0.04));
  const Obb above = box(Vector3d(0, 0, 0.04 + 0.01 + 0.005), Vector3d(0.2, 0.1, 0.01));
  CHECK(pair_geometry(above, low).stacked);
  CHECK(extract_contact(above, low, kParams));
  // A 1 cm lateral gap between side-by-side boxes is never contact (lateral tolerance 4 mm).
  const Obb side = box(Vector3d(0.2 + 0.01, 0, 0.1), Vector3d(0.2, 0.2, 0.2));
  CHECK_FALSE(extract_contact(side, big, kParams));
}

TEST_CASE("overlap: the cells skipped as outside the larger box change no count", "[geometry]") {
  // shared_volume_fraction samples an 8 x 8 x 8 grid of the smaller box and tests only the
  // cells whose coordinates along its axes lie within the larger box's extent along them. The
  // same count over every cell, here, for random pairs of boxes cutting each other:
  auto every_cell = [](const Obb& a, const Obb& b) {
    const Obb& small = a.half.prod() <= b.half.prod() ? a : b;
    const Obb& large = &small == &a ? b : a;
    int inside = 0;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = 0; k < 8; ++k) {
          const Vector3d cell((2.0 * i + 1.0) / 8 - 1.0, (2.0 * j + 1.0) / 8 - 1.0, (2.0 * k + 1.0) / 8 - 1.0);
          inside += large.contains(small.center + small.axes * cell.cwiseProduct(small.half)) ? 1 : 0;
        }
    return inside / 512.0;
  };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int partial = 0;
  for (int n = 0; n < 400; ++n) {
    const Vector3d size_a(0.02 + 0.1 * std::abs(u(rng)), 0.02 + 0.1 * std::abs(u(rng)), 0.02 + 0.1 * std::abs(u(rng)));
    const Vector3d size_b(0.02 + 0.1 * std::abs(u(rng)), 0.02 + 0.1 * std::abs(u(rng)), 0.02 + 0.1 * std::abs(u(rng)));
    const Obb a = box(Vector3d(0, 0, 0.1), size_a, rot(90.0 * u(rng), Vector3d(u(rng), u(rng), u(rng))));
    const Obb b = box(Vector3d(0.06 * u(rng), 0.06 * u(rng), 0.1 + 0.06 * u(rng)), size_b,
                      rot(90.0 * u(rng), Vector3d(u(rng), u(rng), u(rng))));
    const double f = shared_volume_fraction(a, b, 0.0);
    INFO(n);
    CHECK(f == every_cell(a, b));
    partial += f > 0.0 && f < 1.0;
  }
  CHECK(partial > 100);  // most pairs cut each other in part
}

TEST_CASE("overlap: shared share of the smaller box, shrunk by the noise; flatter by tilt", "[geometry]") {
  const Obb a = cube_on_table();
  CHECK(shared_volume_fraction(a, a, 0.0) == Approx(1.0));
  // Shifted by half its width: half of it inside the other (the grid has no cell on the cut).
  const Obb half = cube_on_table(0.0, Vector3d(0.05, 0.0, 0.0));
  CHECK(shared_volume_fraction(a, half, 0.0) == Approx(0.5));
  CHECK(shared_volume_fraction(half, a, 0.0) == Approx(0.5));
  // Shrinking both by 1 cm per side: 8 cm cubes 5 cm apart share 3 of 8 cm.
  CHECK(shared_volume_fraction(a, half, 0.01) == Approx(0.375));
  CHECK(extract_overlap(a, half, 0.0, 0.5));
  CHECK_FALSE(extract_overlap(a, half, 0.01, 0.5));
  // A small box inside a large one: all of the smaller one.
  const Obb small = box(Vector3d(0.0, 0.0, 0.05), Vector3d(0.02, 0.02, 0.02));
  CHECK(shared_volume_fraction(a, small, 0.0) == Approx(1.0));
  // Two boxes pressed 3 mm into each other by noise share 3 % of a 10 cm cube; apart: nothing.
  CHECK(shared_volume_fraction(a, cube_on_table(0.0, Vector3d(0.097, 0.0, 0.0)), 0.0) < 0.07);
  CHECK(shared_volume_fraction(a, cube_on_table(0.0, Vector3d(0.2, 0.0, 0.0)), 0.0) == 0.0);
  // Shrunk to nothing: no shared volume.
  CHECK(shared_volume_fraction(a, a, 0.06) == 0.0);

  const Obb tilted = box(Vector3d(0.0, 0.0, 0.05), Vector3d(0.1, 0.1, 0.1), rot(3.0, Vector3d::UnitX()));
  const double margin = 0.5 * std::numbers::pi / 180.0;
  CHECK(extract_flatter(a, tilted, margin));
  CHECK_FALSE(extract_flatter(tilted, a, margin));
  CHECK_FALSE(extract_flatter(a, a, 0.0));
  CHECK_FALSE(extract_flatter(a, tilted, 5.0 * std::numbers::pi / 180.0));
}
