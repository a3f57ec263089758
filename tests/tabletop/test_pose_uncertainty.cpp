// The pose uncertainty the data imply: the keypoint fit with its Laplace covariance
// (stdlib/tabletop/keypoint_fit.h), the gap noise of resting objects (gap_noise.h) and the
// keypoints' pixel noise (pixel_noise.h).
#include <catch2/catch.hpp>

#include <random>

#include "stdlib/tabletop/gap_noise.h"
#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/pixel_noise.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::tests::tabletop;

namespace {

// A camera 1 m above the table looking down at 45 degrees, one box with keypoints on its
// corners and face centres, projected at `truth` with Gaussian pixel noise.
tt::Scene keypoint_scene(const tt::Pose& truth, double pixel_sigma, std::uint64_t seed) {
  tt::Scene s;
  s.camera = {615, 615, 320, 240, 640, 480};
  tt::Pose cam_in_table;
  cam_in_table.t = Eigen::Vector3d(0, -0.7, 0.7);
  // Camera z axis towards the table origin, x along the table x axis.
  const Eigen::Vector3d z = (-cam_in_table.t).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  cam_in_table.q = Eigen::Quaterniond(r);
  s.table_in_camera = cam_in_table.inverse();
  tt::SceneObject o = object("a", truth.t, Eigen::Vector3d(0.12, 0.08, 0.06));
  o.pose = truth;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, pixel_sigma);
  const Eigen::Isometry3d cam = s.table_in_camera.compose(truth).isometry();
  for (int sx = -1; sx <= 1; ++sx)
    for (int sy = -1; sy <= 1; ++sy)
      for (int sz = -1; sz <= 1; sz += 2) {
        const Eigen::Vector3d p(0.06 * sx, 0.04 * sy, 0.03 * sz);
        const auto uv = tt::project(s.camera, cam * p);
        REQUIRE(uv);
        o.keypoints_model.push_back(p);
        o.keypoints_image.push_back(*uv + Eigen::Vector2d(noise(rng), noise(rng)));
      }
  s.objects.push_back(o);
  return s;
}

}  // namespace

TEST_CASE("keypoint fit: recovers the pose from a noisy estimate, covariance shrinks with pixel noise") {
  tt::Pose truth;
  truth.t = Eigen::Vector3d(0.02, 0.01, 0.03);
  truth.q = Eigen::Quaterniond(rot(20, Eigen::Vector3d::UnitZ()));
  for (const double sigma : {0.5, 2.0}) {
    tt::Scene s = keypoint_scene(truth, sigma, 3);
    s.objects[0].pose.t += Eigen::Vector3d(0.006, -0.004, 0.005);  // the estimate is off
    s.objects[0].pose.q = Eigen::Quaterniond(rot(2.0, Eigen::Vector3d(1, 1, 0))) * s.objects[0].pose.q;
    tt::KeypointFitParams p;
    p.sigma_px = sigma;
    const tt::KeypointFit fit = tt::fit_keypoints(s, s.objects[0], p);
    REQUIRE(fit.ok);
    CHECK(fit.inliers == 18);
    const tt::Vector6d d = tt::pose_delta(truth, fit.mean);
    // Within 4 standard deviations of the truth in every coordinate.
    for (int i = 0; i < 6; ++i) CHECK(std::abs(d(i)) <= 4.0 * std::sqrt(fit.covariance(i, i)));
    CHECK(fit.bottom_sigma > 0.0);
    if (sigma == 0.5) CHECK(fit.bottom_sigma < 0.004);
  }
  tt::Scene s = keypoint_scene(truth, 1.0, 3);
  s.objects[0].keypoints_model.resize(3);
  s.objects[0].keypoints_image.resize(3);
  CHECK_FALSE(tt::fit_keypoints(s, s.objects[0]).ok);  // fewer than 4 keypoints
}

TEST_CASE("keypoint fit: the proposal density is the density of its samples") {
  tt::Pose truth;
  truth.t = Eigen::Vector3d(0.0, 0.0, 0.03);
  const tt::Scene s = keypoint_scene(truth, 1.0, 4);
  const tt::KeypointFit fit = tt::fit_keypoints(s, s.objects[0]);
  REQUIRE(fit.ok);
  // Samples: mean and covariance of the tangent coordinates match scale² Σ.
  std::mt19937_64 rng(9);
  const double scale = 0.5;
  tt::Vector6d mean = tt::Vector6d::Zero();
  tt::Matrix6d cov = tt::Matrix6d::Zero();
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const tt::Vector6d d = tt::pose_delta(fit.mean, tt::sample_fit(fit, scale, rng));
    mean += d / n;
    cov += d * d.transpose() / n;
  }
  const tt::Matrix6d expected = scale * scale * fit.covariance;
  for (int i = 0; i < 6; ++i) {
    CHECK(std::abs(mean(i)) < 0.1 * std::sqrt(expected(i, i)));
    CHECK(cov(i, i) == Approx(expected(i, i)).epsilon(0.1));
  }
  // The density peaks at the mean and falls as a Gaussian along a coordinate.
  tt::Vector6d step = tt::Vector6d::Zero();
  step(2) = std::sqrt(expected(2, 2));
  const double at_mean = tt::fit_log_density(fit, scale, fit.mean);
  const double one_sd = tt::fit_log_density(fit, scale, tt::pose_plus(fit.mean, step));
  const double conditional = 0.5 * step(2) * step(2) * expected.inverse()(2, 2);
  CHECK(at_mean - one_sd == Approx(conditional).epsilon(1e-6));
}

TEST_CASE("gap noise: robust scale of resting gaps, outliers ignored") {
  tt::Scene s;
  const Eigen::Vector3d size(0.1, 0.1, 0.05);
  // Eight boxes on the table with gaps of ±2 mm, one 3 cm above it (hidden or false: ignored
  // beyond the 3 cm reach), one tilted by 30 degrees (not resting on a face).
  const double gaps[] = {0.002, -0.002, 0.002, -0.002, 0.002, -0.002, 0.002, -0.002};
  for (int i = 0; i < 8; ++i)
    s.objects.push_back(object("b" + std::to_string(i), Eigen::Vector3d(0.2 * i, 0, 0.025 + gaps[i]), size));
  s.objects.push_back(object("up", Eigen::Vector3d(2.0, 0, 0.025 + 0.05), size));
  s.objects.push_back(object("tilt", Eigen::Vector3d(2.5, 0, 0.04), size, rot(30, Eigen::Vector3d::UnitX())));
  const tt::GapNoise n = tt::gap_noise(s, 10.0 * 3.14159265358979323846 / 180.0);
  CHECK(n.gaps == 8);
  CHECK(n.sigma == Approx(1.4826 * 0.002).epsilon(1e-6));
  CHECK(tt::vertical_tolerance(n, 3.0, 0.005, 0.015) == Approx(3.0 * 1.4826 * 0.002).epsilon(1e-6));
  // A box on another box: its gap is to the top face below it, not to the table.
  s.objects.push_back(object("top", Eigen::Vector3d(0.0, 0.0, 0.05 + 0.002 + 0.025 + 0.002), size));
  CHECK(tt::gap_noise(s, 0.17).gaps == 9);
  // Too few gaps: the fixed tolerance.
  tt::Scene one;
  one.objects.push_back(s.objects[0]);
  CHECK(tt::vertical_tolerance(tt::gap_noise(one, 0.17), 3.0, 0.005, 0.015) == 0.015);
}

TEST_CASE("pixel noise of a scene: the robust scale of the residuals at the keypoint fits") {
  tt::Pose truth;
  truth.t = Eigen::Vector3d(0.0, 0.0, 0.03);
  for (const double sigma : {0.5, 2.5}) {
    tt::Scene s = keypoint_scene(truth, sigma, 11);
    CHECK(tt::pixel_noise(s).sigma == 0.0);  // 36 residuals: too few to judge by
    CHECK(tt::pixel_noise(s).residuals == 36);
    for (const std::uint64_t seed : {12u, 13u, 14u}) {  // three more boxes, 144 residuals
      tt::Scene more = keypoint_scene(truth, sigma, seed);
      more.objects[0].id = "b" + std::to_string(seed);
      more.objects[0].pose.t.x() += 0.002;  // estimates a little off: the fit starts there
      s.objects.push_back(more.objects[0]);
    }
    const tt::PixelNoise n = tt::pixel_noise(s);
    CHECK(n.residuals == 144);
    // The fit takes 6 of each object's 36 degrees of freedom: about sigma · sqrt(30/36).
    CHECK(n.sigma > 0.7 * sigma);
    CHECK(n.sigma < 1.2 * sigma);
  }
}
