// Keypoint likelihood (eq. 4.4) and the DDMCMC pose proposal (eqs. 4.6/4.7).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/pose_proposal.h"
#include "tests/tabletop/tabletop_test_util.h"

using namespace ksmc::stdlib::tabletop;
using ksmc::tests::tabletop::object;
using ksmc::tests::tabletop::rot;
using Eigen::Vector3d;

namespace {

// Camera 0.8 m above the table looking down a little obliquely; one 10 cm box with
// 12 keypoints whose observations are the exact projections of the true pose.
Scene scene_with_keypoints() {
  Scene s;
  s.camera = {615, 615, 320, 240, 640, 480};
  s.table_in_camera.t = Vector3d(0.02, 0.05, 0.8);
  s.table_in_camera.q = Eigen::Quaterniond(rot(160, Vector3d::UnitX()));
  SceneObject o = object("box", Vector3d(0.03, -0.02, 0.05), Vector3d(0.1, 0.08, 0.1), rot(25, Vector3d::UnitZ()));
  for (int k = 0; k < 8; ++k) o.keypoints_model.push_back(o.obb().half.cwiseProduct(
                                  Vector3d((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1)));
  o.keypoints_model.push_back(Vector3d(0.01, 0.02, 0.05));
  o.keypoints_model.push_back(Vector3d(-0.03, 0.0, 0.05));
  o.keypoints_model.push_back(Vector3d(0.05, 0.01, -0.02));
  o.keypoints_model.push_back(Vector3d(0.0, 0.04, 0.03));
  const Eigen::Isometry3d cam = s.table_in_camera.compose(o.pose).isometry();
  for (const auto& m : o.keypoints_model) o.keypoints_image.push_back(*project(s.camera, cam * m));
  s.objects.push_back(o);
  return s;
}

}  // namespace

TEST_CASE("pinhole projection", "[likelihood]") {
  const Camera c{600, 500, 320, 240, 640, 480};
  const auto uv = project(c, Vector3d(0.1, -0.2, 2.0));
  REQUIRE(uv);
  CHECK(uv->x() == Approx(350.0));
  CHECK(uv->y() == Approx(190.0));
  CHECK_FALSE(project(c, Vector3d(0.1, 0.1, -1.0)));
  CHECK_FALSE(project(c, Vector3d(0.1, 0.1, 0.0)));
}

TEST_CASE("Gaussian likelihood: value at the true pose and maximum there", "[likelihood]") {
  const Scene s = scene_with_keypoints();
  const SceneObject& o = s.objects[0];
  const double at_truth = keypoint_log_likelihood(s, o, o.pose);
  const double n = static_cast<double>(o.keypoints_model.size());
  CHECK(at_truth == Approx(-n * std::log(2.0 * std::numbers::pi)).epsilon(1e-9));
  CHECK(scene_log_likelihood(s) == Approx(at_truth));
  // Every small perturbation in any of the 6 directions lowers it.
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      Pose p = o.pose;
      p.t[axis] += sign * 0.001;
      CHECK(keypoint_log_likelihood(s, o, p) < at_truth - 1e-3);
      Pose r = o.pose;
      r.q = (Eigen::Quaterniond(rot(sign * 0.2, Vector3d::Unit(axis))) * r.q).normalized();
      CHECK(keypoint_log_likelihood(s, o, r) < at_truth - 1e-3);
    }
  }
  // A one-pixel residual in u costs exactly 1/2 with σ = 1 px, 1/8 with σx = 2 px.
  Scene shifted = s;
  shifted.objects[0].keypoints_image[0].x() += 1.0;
  CHECK(keypoint_log_likelihood(shifted, shifted.objects[0], o.pose) == Approx(at_truth - 0.5));
  KeypointLikelihoodParams wide;
  wide.sigma_x_px = 2.0;
  CHECK(keypoint_log_likelihood(shifted, shifted.objects[0], o.pose, wide) ==
        Approx(keypoint_log_likelihood(s, o, o.pose, wide) - 0.125));
  // Behind the camera: impossible under the Gaussian model.
  Pose behind = o.pose;
  behind.t.z() = 2.0;  // 2 m above the table = 1.2 m behind a camera 0.8 m up
  CHECK(keypoint_log_likelihood(s, o, behind) == -std::numeric_limits<double>::infinity());
}

TEST_CASE("robust likelihood bounds the cost of an outlier keypoint", "[likelihood]") {
  Scene s = scene_with_keypoints();
  s.objects[0].keypoints_image[3] += Eigen::Vector2d(150.0, -90.0);  // a wrong match
  const SceneObject& o = s.objects[0];
  KeypointLikelihoodParams robust;
  robust.robust = true;
  const double w = robust.outlier_weight;
  const double floor_per_point = std::log(w / (640.0 * 480.0));
  const double at_truth = keypoint_log_likelihood(s, o, o.pose, robust);
  // 11 inliers near their Gaussian peak + one outlier near the uniform floor.
  const double inlier = std::log((1 - w) / (2 * std::numbers::pi) + w / (640.0 * 480.0));
  CHECK(at_truth == Approx(11 * inlier + floor_per_point).epsilon(1e-6));
  // The true pose still beats nearby poses, while the plain Gaussian is dominated by the outlier.
  Pose p = o.pose;
  p.t.x() += 0.002;
  CHECK(keypoint_log_likelihood(s, o, p, robust) < at_truth);
  CHECK(keypoint_log_likelihood(s, o, o.pose) < at_truth - 1000.0);
  KeypointLikelihoodParams bad = robust;
  bad.outlier_weight = 1.0;
  CHECK_THROWS_AS(keypoint_log_likelihood(s, o, o.pose, bad), std::invalid_argument);
}

TEST_CASE("proposal Q of eqs. 4.6 and 4.7", "[proposal]") {
  const std::vector<double> lw = {std::log(1.0), std::log(2.0), std::log(3.0)};
  const ProposalQ q = proposal_q(lw, std::log(4.0));
  CHECK(q.best == 2);
  CHECK(std::exp(q.log_q_forward) == Approx(3.0 / 10.0));
  CHECK(std::exp(q.log_q_backward) == Approx(4.0 / 10.0));
  // Log weights far below exp's range (real keypoint likelihoods) stay exact.
  const std::vector<double> tiny = {-5000.0, -5000.0 + std::log(2.0), -5000.0 + std::log(3.0)};
  const ProposalQ qt = proposal_q(tiny, -5000.0 + std::log(4.0));
  CHECK(qt.best == 2);
  CHECK(qt.log_q_forward == Approx(std::log(0.3)));
  CHECK(qt.log_q_backward == Approx(std::log(0.4)));
  // Ties pick the first; impossible candidates are never chosen.
  const double ninf = -std::numeric_limits<double>::infinity();
  const std::vector<double> tie = {ninf, 0.0, 0.0};
  const ProposalQ qq = proposal_q(tie, ninf);
  CHECK(qq.best == 1);
  CHECK(std::exp(qq.log_q_forward) == Approx(0.5));
  CHECK(qq.log_q_backward == ninf);
  const std::vector<double> none = {ninf, ninf};
  CHECK(proposal_q(none, 0.0).best == -1);
}

TEST_CASE("pose proposal: best candidate, exact Q, determinism by seed", "[proposal]") {
  Scene s = scene_with_keypoints();
  // Start 4 mm / 2° off the truth so candidates can improve.
  s.objects[0].pose.t += Vector3d(0.004, -0.002, 0.001);
  s.objects[0].pose.q = (Eigen::Quaterniond(rot(2, Vector3d(1, 1, 0))) * s.objects[0].pose.q).normalized();
  const PoseProposalParams params;  // n = 20
  std::mt19937_64 rng(42);
  const PoseProposal p = propose_pose(s, 0, params, {}, rng);
  REQUIRE(p.valid);
  REQUIRE(p.candidates.size() == 20);
  for (double w : p.candidate_log_weights) CHECK(w <= p.log_weight_proposed);
  CHECK(p.log_weight_proposed == Approx(keypoint_log_likelihood(s, s.objects[0], p.pose)));
  // Q recomputed by hand from the weights (eq. 4.6, 4.7).
  double hi = p.log_weight_current;
  for (double w : p.candidate_log_weights) hi = std::max(hi, w);
  double total = std::exp(p.log_weight_current - hi);
  for (double w : p.candidate_log_weights) total += std::exp(w - hi);
  CHECK(p.log_q_forward == Approx(p.log_weight_proposed - hi - std::log(total)));
  CHECK(p.log_q_backward == Approx(p.log_weight_current - hi - std::log(total)));
  // Candidates are spread with roughly σ_t = 3 mm.
  double sq = 0.0;
  for (const auto& c : p.candidates) sq += (c.t - s.objects[0].pose.t).squaredNorm();
  const double rms = std::sqrt(sq / (3.0 * 20.0));
  CHECK(rms > 0.0015);
  CHECK(rms < 0.0050);

  std::mt19937_64 same(42);
  const PoseProposal again = propose_pose(s, 0, params, {}, same);
  CHECK(again.best == p.best);
  CHECK(again.pose.t == p.pose.t);
  CHECK(again.pose.q.coeffs() == p.pose.q.coeffs());
  CHECK(again.candidate_log_weights == p.candidate_log_weights);
  std::mt19937_64 other(43);
  const PoseProposal different = propose_pose(s, 0, params, {}, other);
  CHECK(different.pose.t != p.pose.t);

  // Repeated best-of-20 steps climb towards the true pose.
  Scene walk = s;
  std::mt19937_64 r2(1);
  const double start = keypoint_log_likelihood(walk, walk.objects[0], walk.objects[0].pose);
  for (int i = 0; i < 30; ++i) {
    const PoseProposal step = propose_pose(walk, 0, params, {}, r2);
    if (step.valid && step.log_weight_proposed > step.log_weight_current) walk.objects[0].pose = step.pose;
  }
  CHECK(keypoint_log_likelihood(walk, walk.objects[0], walk.objects[0].pose) > start + 100.0);
  CHECK_THROWS_AS(propose_pose(s, 3, params, {}, rng), std::out_of_range);
}
