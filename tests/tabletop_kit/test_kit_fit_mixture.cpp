// keypoints.gaussian sigma_from_scene (kit_likelihood.h), and pose.fit with estimate_scale
// (fit_kernel.h): the mixture's exact density, draws from both
// parts, its refusal without a pose-estimate term, and the state it exists for: a real box
// whose noisy estimate sinks 28 mm into the table, where the refine move alone stays
// (pose_noise family, batch seed 2027, scene 5, box_9;
// docs/tabletop_families/fit_kernel.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "runtime/domain/config_error.h"
#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/kit/fit_kernel.h"
#include "stdlib/tabletop/kit/kit_likelihood.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/scene_io.h"
#include "tests/tabletop_kit/binding_fixture.h"
#include "tests/tabletop_kit/e2e_support.h"
#include "tools/tabletop_families/families.h"
#include "tools/tabletop_sim/scene_writer.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace tt = ksmc::stdlib::tabletop;
namespace tf = ksmc::tools::tabletop_families;
namespace sim = ksmc::tools::tabletop_sim;
using namespace ksmc::tests::tabletop_kit;

namespace {

using Decl = ksmc::runtime::domain::KernelDecl<blk::Move, blk::Source>;

const Decl& fit_decl(const blk::Binding& b) {
  for (const auto& k : b.kernels)
    if (k.name == "fit") return k;
  FAIL("domains/tabletop.ksm declares no kernel 'fit'");
  return b.kernels.front();
}

double log_mix(double a, double b) {
  const double m = std::max(a, b);
  return m + std::log(0.5 * std::exp(a - m) + 0.5 * std::exp(b - m));
}

struct Case {
  sim::GeneratedScene g;
  std::shared_ptr<const tt::Scene> scene;
  std::size_t object = 0;  // box_9
};

Case sunk_box() {
  Case c;
  const tf::Family& f = tf::family("pose_noise");
  c.g = tf::generate(f, tf::family_scene_seed(f, 2027, 5));
  auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(c.g)), "scene", ".");
  c.scene = std::make_shared<const tt::Scene>(std::move(load.scene));
  const int idx = c.scene->find("box_9");
  REQUIRE(idx >= 0);
  c.object = static_cast<std::size_t>(idx);
  return c;
}

double lowest_z(const tt::Scene& s, std::size_t object, const tt::Pose& pose) {
  return tt::Obb::from_pose(pose, s.objects[object].size).min_z();
}

}  // namespace

TEST_CASE("pose.fit estimate_scale: the domain's kernel, the mixture's exact density, both parts drawn") {
  const blk::Binding& b = ksm_binding();
  const auto& decl = fit_decl(b);
  const auto& src = std::get<blk::PoseFit>(decl.sources.at(0));
  CHECK(src.scale == 1.0);
  CHECK(src.estimate_scale == 2.0);
  const double st = b.likelihood.estimate_sigma_t, sr = b.likelihood.estimate_sigma_r;
  const kit::FitKernel k(decl, st, sr);

  const Case c = sunk_box();
  kit::TabletopModel model(c.scene, b);
  ksmc::runtime::mcmc::Rng rng(11);
  int near_fit = 0, near_estimate = 0, made = 0;
  for (int i = 0; i < 400; ++i) {
    const auto before = model.scene().objects;
    const auto p = k.propose(model, rng);
    if (!model.in_move()) continue;
    ++made;
    std::size_t moved = before.size();
    for (std::size_t j = 0; j < before.size(); ++j)
      if (!(model.scene().objects[j].pose.t - before[j].pose.t).isZero()) moved = j;
    REQUIRE(moved < before.size());
    const auto& fit = model.block_scene().fit(blk::Scene::body_of_object(moved));
    tt::KeypointFit estimate;
    estimate.ok = true;
    estimate.mean = c.scene->objects[moved].pose;
    estimate.covariance = tt::Matrix6d::Zero();
    estimate.covariance.diagonal() << st * st, st * st, st * st, sr * sr, sr * sr, sr * sr;
    const tt::Pose& now = model.scene().objects[moved].pose;
    const double pick = -std::log(static_cast<double>(model.observed_objects().size()));
    const double a = tt::fit_log_density(fit, 1.0, now), e = tt::fit_log_density(estimate, 2.0, now);
    CHECK(p.log_q_fwd == Approx(log_mix(a, e) + pick).epsilon(1e-9));
    CHECK(p.log_q_bwd == Approx(log_mix(tt::fit_log_density(fit, 1.0, before[moved].pose),
                                        tt::fit_log_density(estimate, 2.0, before[moved].pose)) + pick)
                             .epsilon(1e-9));
    (a > e ? near_fit : near_estimate) += 1;
    model.reject();
  }
  REQUIRE(made > 300);
  // Each part draws about half; a draw sits where its own part's density is the higher one
  // unless the parts overlap (an estimate close to its fit).
  CHECK(near_fit > made / 4);
  CHECK(near_estimate > made / 4);
}

TEST_CASE("pose.fit estimate_scale needs the likelihood's pose-estimate term") {
  const blk::Binding& b = ksm_binding();
  const auto& decl = fit_decl(b);
  CHECK_THROWS_AS(kit::FitKernel(decl, 0.0, b.likelihood.estimate_sigma_r), ksmc::runtime::domain::ConfigError);
  CHECK_THROWS_WITH(kit::FitKernel(decl, b.likelihood.estimate_sigma_t, 0.0), Catch::Contains("estimate_sigma_r above 0"));
  blk::Binding off = b;
  off.likelihood.estimate_sigma_t = 0.0;
  CHECK_THROWS_WITH(kit::check_binding(off), Catch::Contains("pose.fit with estimate_scale > 0"));
}

TEST_CASE("a box whose estimate sinks 28 mm into the table: the mixture move reaches its keypoints' pose") {
  const Case c = sunk_box();
  const double truth = 1e3 * tt::Obb::from_pose(tt::Pose{c.g.objects[c.object].clean_pose.t, c.g.objects[c.object].clean_pose.q},
                                               c.scene->objects[c.object].size).min_z();
  const double input = 1e3 * lowest_z(*c.scene, c.object, c.scene->objects[c.object].pose);
  REQUIRE(std::abs(truth) < 1.0);  // it rests on the table
  REQUIRE(input < -25.0);

  const blk::Binding& domain = ksm_binding();
  blk::Binding refine_only = domain;
  refine_only.kernels.resize(1);
  REQUIRE(refine_only.kernels[0].name == "refine");
  refine_only.schedule.at(0).probabilities = {{"refine", 1.0}};

  const auto stuck = run_kit(refine_only, c.scene, 2000, 6);
  const auto moved = run_kit(domain, c.scene, 2000, 6);
  const double z_stuck = 1e3 * lowest_z(stuck.scene, c.object, stuck.scene.objects[c.object].pose);
  const double z_moved = 1e3 * lowest_z(moved.scene, c.object, moved.scene.objects[c.object].pose);
  INFO("lowest z: truth " << truth << " mm, input " << input << ", refine only " << z_stuck << ", refine + fit " << z_moved);
  CHECK(z_stuck < -15.0);            // the refine move alone stays near the estimate
  CHECK(std::abs(z_moved - truth) < 8.0);
  CHECK(moved.probabilities[c.object].false_prob < 0.4);  // no longer read as a false estimate
  CHECK(stuck.probabilities[c.object].false_prob > 0.6);
}

TEST_CASE("keypoints.gaussian sigma_from_scene: the scene's pixel noise raises sigma and outlier_px") {
  const blk::Binding& b = ksm_binding();
  REQUIRE(b.likelihood.sigma_from_scene);
  REQUIRE(b.likelihood.sigma_px == 1.0);
  const Case c = sunk_box();  // keypoints with 1 px noise
  const auto own = kit::scene_likelihood(*c.scene, b.likelihood);
  CHECK(own.sigma_px >= 1.0);
  CHECK(own.sigma_px < 1.3);
  // 3 px more noise on every keypoint: about sqrt(1 + 9) px.
  tt::Scene noisy = *c.scene;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> px(0.0, 3.0);
  for (auto& o : noisy.objects)
    for (auto& uv : o.keypoints_image) uv += Eigen::Vector2d(px(rng), px(rng));
  const auto scaled = kit::scene_likelihood(noisy, b.likelihood);
  CHECK(scaled.sigma_px > 2.4);
  CHECK(scaled.sigma_px < 3.6);
  CHECK(scaled.outlier_px == Approx(b.likelihood.outlier_px * scaled.sigma_px / b.likelihood.sigma_px));
  CHECK(scaled.estimate_sigma_t == b.likelihood.estimate_sigma_t);
  // The model scores with it; without the flag, with the declared values.
  const kit::TabletopModel model(std::make_shared<const tt::Scene>(noisy), b);
  CHECK(model.likelihood().sigma_px == scaled.sigma_px);
  blk::Binding fixed = b;
  fixed.likelihood.sigma_from_scene = false;
  CHECK(kit::scene_likelihood(noisy, fixed.likelihood).sigma_px == 1.0);
  CHECK(kit::scene_likelihood(noisy, fixed.likelihood).outlier_px == b.likelihood.outlier_px);
}
