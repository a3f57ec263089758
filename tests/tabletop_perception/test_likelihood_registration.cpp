// Cloud likelihood (Gaussian on the point-to-surface distance, incremental per object) and
// the rigid registration with unknown correspondences.
#include <catch2/catch.hpp>

#include <random>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/registration.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::Obb;
using namespace ksmc::stdlib::tabletop;

namespace {
Obb upright(const Eigen::Vector3d& c, const Eigen::Vector3d& size, double yaw = 0.0) {
  Obb b;
  b.center = c;
  b.axes = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  b.half = 0.5 * size;
  return b;
}
}  // namespace

TEST_CASE("surface distance inside and outside the box", "[perception][likelihood]") {
  const Obb b = upright(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.2, 0.1, 0.1));
  CHECK(surface_distance(b, Eigen::Vector3d(0.1, 0.0, 0.0)) == Approx(0.0).margin(1e-12));
  CHECK(surface_distance(b, Eigen::Vector3d(0.0, 0.0, 0.0)) == Approx(0.05));
  CHECK(surface_distance(b, Eigen::Vector3d(0.13, 0.09, 0.0)) == Approx(std::hypot(0.03, 0.04)));
}

TEST_CASE("cloud likelihood peaks at the true box and updates incrementally", "[perception][likelihood]") {
  const Eigen::Vector3d size(0.12, 0.06, 0.2);
  Points a, b;
  ksmc::tests::perception::add_box(a, 0.0, 0.0, 0.3, size, 0.01);
  ksmc::tests::perception::add_box(b, 0.3, 0.1, 0.0, Eigen::Vector3d(0.08, 0.08, 0.05), 0.01);
  const Obb ta = upright(Eigen::Vector3d(0, 0, 0.1), size, 0.3);
  const Obb tb = upright(Eigen::Vector3d(0.3, 0.1, 0.025), Eigen::Vector3d(0.08, 0.08, 0.05));
  CloudLikelihoodParams params;
  params.robust = false;
  const double at_truth = cloud_log_likelihood(a, ta, params);
  for (const Eigen::Vector3d& shift : {Eigen::Vector3d(0.005, 0, 0), Eigen::Vector3d(0, 0, -0.01)}) {
    Obb moved = ta;
    moved.center += shift;
    CHECK(cloud_log_likelihood(a, moved, params) < at_truth);
  }
  Obb turned = ta;
  turned.axes = Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  CHECK(cloud_log_likelihood(a, turned, params) < at_truth);
  // Robust: a far box costs a bounded amount per point.
  Obb far = ta;
  far.center.x() += 1.0;
  const double capped = cloud_log_likelihood(a, far, {});
  CHECK(capped == Approx(-static_cast<double>(a.size()) *
                         (0.02 * 0.02 / (2 * 0.004 * 0.004) + std::log(0.012 * std::sqrt(2 * 3.14159265358979)))));

  CloudLikelihood cl({a, b}, {ta, tb}, params);
  CHECK(cl.total() == Approx(at_truth + cloud_log_likelihood(b, tb, params)));
  Obb moved = tb;
  moved.center.z() += 0.004;
  const double predicted = cl.evaluate(1, moved);
  const double delta = cl.update(1, moved);
  CHECK(cl.term(1) == Approx(predicted));
  CHECK(delta < 0.0);
  CHECK(cl.total() == Approx(cl.term(0) + cl.term(1)));
  CHECK(cl.total() == Approx(at_truth + cloud_log_likelihood(b, moved, params)));
  CHECK(cloud_log_likelihood({}, ta) == 0.0);
}

TEST_CASE("cloud likelihood: a point inside the box costs less than one as far outside", "[perception][likelihood]") {
  const Obb box = upright(Eigen::Vector3d(0, 0, 0.1), Eigen::Vector3d(0.1, 0.1, 0.2));
  const Points inside{Eigen::Vector3d(0.04, 0, 0.1)}, outside{Eigen::Vector3d(0.06, 0, 0.1)};  // 1 cm off the +x face
  CHECK(signed_surface_distance(box, inside[0]) == Approx(-0.01));
  CHECK(signed_surface_distance(box, outside[0]) == Approx(0.01));
  CHECK(cloud_log_likelihood(inside, box) > cloud_log_likelihood(outside, box));
  CloudLikelihoodParams symmetric;
  symmetric.inside_sigma = symmetric.sigma;
  CHECK(cloud_log_likelihood(inside, box, symmetric) == Approx(cloud_log_likelihood(outside, box, symmetric)));

  // A carton with a gable top: the sides' points up to 20 cm, a roof sloping from 20 to
  // 24 cm. Its bounding box (0-24 cm) is the best; with sigma on both sides the box would
  // rather sink, its top face through the roof (a real Kinect frame's carton sank 15 mm).
  Points carton;
  for (double z = 0.0; z <= 0.2; z += 0.005)
    for (double y = -0.05; y <= 0.05; y += 0.005) carton.emplace_back(-0.05, y, z);
  for (double x = -0.05; x <= 0.05; x += 0.005)
    for (double y = -0.05; y <= 0.05; y += 0.005) carton.emplace_back(x, y, 0.24 - 0.8 * std::abs(y));
  const Eigen::Vector3d size(0.1, 0.1, 0.24);
  const auto ll_at = [&](double dz, const CloudLikelihoodParams& p) {
    return cloud_log_likelihood(carton, upright(Eigen::Vector3d(0, 0, 0.12 + dz), size), p);
  };
  const CloudLikelihoodParams bounding;
  CHECK(ll_at(0.0, bounding) > ll_at(-0.015, bounding));
  CHECK(ll_at(0.0, bounding) > ll_at(0.005, bounding));
  CHECK(ll_at(-0.015, symmetric) > ll_at(0.0, symmetric));
}

TEST_CASE("cloud likelihood: inside a box, points are not measured to the face it stands on", "[perception][likelihood]") {
  const Obb box = upright(Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(0.08, 0.08, 0.1));
  const Eigen::Vector3d sensor(0.6, 0.0, 0.5);  // above the table, beyond the +x face
  // 1 cm over the bottom face, 3 cm behind the +x face: the bottom is the nearest face, but
  // the box stands on it; the next nearest is +x.
  const Eigen::Vector3d low(0.01, 0.0, 0.01);
  CHECK(signed_surface_distance(box, low) == Approx(-0.01));
  CHECK(signed_seen_surface_distance(box, low, sensor) == Approx(-0.03));
  // Faces the sensor cannot see but that do not point down still count: 1 cm inside -y.
  CHECK(signed_seen_surface_distance(box, Eigen::Vector3d(0.0, -0.03, 0.05), sensor) == Approx(-0.01));
  // Outside, the distance is the box's, whichever face.
  CHECK(signed_seen_surface_distance(box, Eigen::Vector3d(0.0, 0.0, -0.01), sensor) == Approx(0.01));
  // A sensor under the box (a glass table) sees its bottom: every face counts.
  CHECK(signed_seen_surface_distance(box, low, Eigen::Vector3d(0.0, 0.0, -0.5)) == Approx(-0.01));
  // A box on its side: the face pointing down is another axis's.
  Obb side = box;
  side.axes.col(1) = Eigen::Vector3d(0, 0, 1);
  side.axes.col(2) = Eigen::Vector3d(0, -1, 0);
  side.half = Eigen::Vector3d(0.04, 0.05, 0.04);
  // 1 cm over the face it lies on; the nearest other face (its -y side) is 3 cm away.
  CHECK(signed_surface_distance(side, Eigen::Vector3d(0.0, 0.01, 0.01)) == Approx(-0.01));
  CHECK(signed_seen_surface_distance(side, Eigen::Vector3d(0.0, 0.01, 0.01), sensor) == Approx(-0.03));

  // A mug (a cylinder of 4 cm radius, 10 cm tall) with a handle, on the table, seen from the
  // sensor: its front half from 12 mm up (the front end leaves the points under 12 mm to the
  // table), its rim with 3 mm of depth noise, the handle's outer side; its bounding box
  // 8 x 12 cm takes the handle in. Measured to every face, the front's lower points pull the
  // box's bottom face up to them, and with the rim's noise pulling its top, the box gains
  // 8.4 nats rising 4 mm and 5.9 rising 8 mm; measured to the faces but the one it stands on,
  // 4.0 and -3.9.
  Points mug;
  for (double a = -1.5; a <= 1.5; a += 0.05)
    for (double z = 0.012; z <= 0.1; z += 0.005) mug.emplace_back(0.04 * std::cos(a), 0.04 * std::sin(a), z);
  int k = 0;
  for (double a = -3.1; a <= 3.1; a += 0.05) mug.emplace_back(0.04 * std::cos(a), 0.04 * std::sin(a), 0.1 + 0.003 * (k++ % 3 - 1));
  for (double z = 0.03; z <= 0.08; z += 0.005) mug.emplace_back(0.0, 0.08, z);
  CloudLikelihoodParams all_faces, seen_faces;
  seen_faces.sensor = sensor;
  const auto ll_at = [&](double dz, const CloudLikelihoodParams& p) {
    return cloud_log_likelihood(mug, upright(Eigen::Vector3d(0, 0.02, 0.05 + dz), Eigen::Vector3d(0.08, 0.12, 0.1)), p);
  };
  CHECK(ll_at(0.008, all_faces) > ll_at(0.0, all_faces));
  CHECK(ll_at(0.0, seen_faces) > ll_at(0.008, seen_faces));
  CHECK(ll_at(0.004, seen_faces) - ll_at(0.0, seen_faces) < ll_at(0.004, all_faces) - ll_at(0.0, all_faces) - 4.0);
  // With the sensor under the table the two agree.
  CloudLikelihoodParams below = seen_faces;
  below.sensor = Eigen::Vector3d(0, 0, -0.5);
  CHECK(ll_at(0.008, below) == Approx(ll_at(0.008, all_faces)));
}

TEST_CASE("registration recovers a rigid motion and the matching from shuffled points", "[perception][registration]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::vector<Eigen::Vector3d> src;
  for (int i = 0; i < 10; ++i) src.emplace_back(u(rng), u(rng), 0.1 * u(rng));
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(2.8, Eigen::Vector3d(0.1, 0.2, 1.0).normalized()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.7, -0.6, -0.1);
  std::vector<int> perm{3, 7, 0, 9, 1, 5, 8, 2, 6, 4};
  std::vector<Eigen::Vector3d> dst(10);
  for (int i = 0; i < 10; ++i)
    dst[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])] =
        t * src[static_cast<std::size_t>(i)] + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  src.emplace_back(5.0, 5.0, 5.0);  // an extra source point with no partner
  const Registration r = register_unmatched(src, dst, 0.02);
  CHECK(r.matched == 10);
  for (int i = 0; i < 10; ++i) CHECK(r.match[static_cast<std::size_t>(i)] == perm[static_cast<std::size_t>(i)]);
  CHECK(r.match[10] == -1);
  CHECK(r.rms < 0.005);
  CHECK((r.source_to_target.linear() - t.linear()).norm() < 0.03);
}

TEST_CASE("free space: a box where the sensor sees through it is penalised", "[perception][likelihood]") {
  const Obb real = upright(Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(0.1, 0.1, 0.1));
  FreeSpace fs;
  fs.sensor = Eigen::Vector3d(0.1, -0.2, 0.9);
  Points raw;
  ksmc::tests::perception::add_table(raw, 0.3, 0.3, 0.01);
  ksmc::tests::perception::add_box(raw, 0.0, 0.0, 0.0, Eigen::Vector3d(0.1, 0.1, 0.1), 0.005);
  // Keep what the sensor sees: rays not blocked by the real box (1 mm before the point).
  FreeSpace probe = fs;
  probe.margin = 0.001;
  for (const auto& p : raw) {
    probe.points = {p};
    if (see_through_count(real, probe) == 0) fs.points.push_back(p);
  }
  REQUIRE(fs.points.size() < raw.size());  // the box hides part of the table and its far faces
  CHECK(see_through_count(real, fs) == 0);
  const Obb floating = upright(Eigen::Vector3d(0.18, 0.15, 0.12), Eigen::Vector3d(0.06, 0.06, 0.06));
  const std::size_t blocked = see_through_count(floating, fs);
  CHECK(blocked > 20);

  Points own;
  for (const auto& p : fs.points)
    if (real.contains(p, 0.002)) own.push_back(p);
  CloudLikelihood cl({own, {}}, {real, floating}, {}, fs);
  CHECK(cl.term(1) == Approx(-fs.cost * static_cast<double>(blocked)));
  CHECK(cl.term(0) == Approx(cloud_log_likelihood(own, real)));
  // Moving the false box out of the sensor's view removes the penalty, incrementally.
  Obb away = floating;
  away.center = Eigen::Vector3d(0.6, 0.6, 0.03);
  CHECK(cl.update(1, away) == Approx(fs.cost * static_cast<double>(blocked)));
  CHECK(cl.total() == Approx(cl.term(0)));
}

TEST_CASE("free space: the ray index counts what the full scan counts", "[perception][likelihood]") {
  // A rendered view of three boxes on a table; random boxes anywhere, also around and
  // behind the sensor.
  FreeSpace fs;
  fs.sensor = Eigen::Vector3d(0.35, -0.5, 0.55);
  const auto box_at = [](double x, double y, const Eigen::Vector3d& size) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(x, y, 0.5 * size.z());
    return ksmc::tests::perception::CastBox{pose, size};
  };
  fs.points = ksmc::tests::perception::cast_view(
      fs.sensor, Eigen::Vector3d(0.0, 0.0, 0.05), 0.5, 0.004,
      {box_at(0.0, 0.0, {0.1, 0.1, 0.1}), box_at(-0.15, 0.1, {0.2, 0.06, 0.05}), box_at(0.12, 0.12, {0.05, 0.08, 0.2})},
      0.6, 0.4);
  REQUIRE(fs.points.size() > 10000);
  const RayIndex index(fs);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int crossed = 0;
  for (int k = 0; k < 300; ++k) {
    const double reach = k < 250 ? 0.35 : 1.2;  // the last 50 also around the sensor
    Obb box = upright(Eigen::Vector3d(reach * u(rng), reach * u(rng), 0.15 + 0.15 * u(rng) + (k >= 250 ? 0.4 : 0.0)),
                      Eigen::Vector3d(0.03 + 0.1 * std::abs(u(rng)), 0.03 + 0.1 * std::abs(u(rng)), 0.03 + 0.1 * std::abs(u(rng))));
    box.axes = Eigen::AngleAxisd(3.0 * u(rng), Eigen::Vector3d(u(rng), u(rng), u(rng) + 2.0).normalized()).toRotationMatrix();
    const std::size_t full = see_through_count(box, fs);
    CHECK(index.see_through_count(box) == full);
    crossed += full > 0;
  }
  CHECK(crossed > 100);  // the boxes were seen through, not all beside the view
}
