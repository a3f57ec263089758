// The kit's checks of a binding: what it cannot run is a ConfigError (an internal error of
// the binary: `ksmc check` enforces the kit contract), and the kernels come from the moves.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "runtime/domain/config_error.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "stdlib/tabletop/kit/fit_kernel.h"
#include "stdlib/tabletop/kit/refine_kernel.h"
#include "stdlib/tabletop/keypoint_fit.h"
#include "tests/tabletop_kit/e2e_support.h"
#include "stdlib/tabletop/scene_io.h"
#include "tests/tabletop_kit/binding_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace rd = ksmc::runtime::domain;
using namespace ksmc::tests::tabletop_kit;

namespace {

std::string binding_error(const blk::Binding& b) {
  try {
    kit::check_binding(b);
  } catch (const rd::ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("the generated binding is the fixture's copy of domains/tabletop.ksm, and the kit runs it") {
  const blk::Binding& g = ksm_binding();
  const blk::Binding& f = ksm_fixture_binding();
  CHECK(binding_error(g) == "(no error)");
  CHECK(g.domain == f.domain);
  REQUIRE(g.extractors.size() == f.extractors.size());
  for (std::size_t i = 0; i < g.extractors.size(); ++i) CHECK(g.extractors[i].predicate == f.extractors[i].predicate);
  CHECK(g.likelihood.sigma_px == f.likelihood.sigma_px);
  CHECK(g.likelihood.robust == f.likelihood.robust);
  CHECK(g.likelihood.outlier_px == f.likelihood.outlier_px);
  CHECK(g.likelihood.sigma_from_scene == f.likelihood.sigma_from_scene);
  CHECK(g.likelihood.keypoint_term == f.likelihood.keypoint_term);
  REQUIRE(g.likelihood.cloud.has_value() == f.likelihood.cloud.has_value());
  if (g.likelihood.cloud) {
    CHECK(g.likelihood.cloud->sigma == f.likelihood.cloud->sigma);
    CHECK(g.likelihood.cloud->robust == f.likelihood.cloud->robust);
    CHECK(g.likelihood.cloud->outlier == f.likelihood.cloud->outlier);
    CHECK(g.likelihood.cloud->free_space_cost == f.likelihood.cloud->free_space_cost);
  }
  REQUIRE(g.outputs.size() == 1);
  CHECK(g.outputs[0].false_est == f.outputs[0].false_est);
  CHECK(g.outputs[0].hidden == f.outputs[0].hidden);
  REQUIRE(g.kernels.size() == 2);
  REQUIRE(f.kernels.size() == 2);
  CHECK(g.kernels[0].name == f.kernels[0].name);
  CHECK(g.kernels[1].name == f.kernels[1].name);
  const auto& gfit = std::get<blk::PoseFit>(g.kernels[1].sources.at(0));
  const auto& ffit = std::get<blk::PoseFit>(f.kernels[1].sources.at(0));
  CHECK(gfit.scale == ffit.scale);
  CHECK(gfit.estimate_scale == ffit.estimate_scale);
  CHECK(g.schedule.at(0).probabilities == f.schedule.at(0).probabilities);
  REQUIRE(g.kernels[0].sources.size() == 1);
  const auto& gs = std::get<blk::PosePerturb>(g.kernels[0].sources[0]);
  const auto& fs = std::get<blk::PosePerturb>(f.kernels[0].sources[0]);
  CHECK(gs.sigma_t == fs.sigma_t);
  CHECK(gs.sigma_r == fs.sigma_r);
  CHECK(gs.candidates == fs.candidates);
  // The extractors of both compute the same evidence on a scene.
  const auto scene = std::make_shared<const ksmc::stdlib::tabletop::Scene>(
      ksmc::stdlib::tabletop::load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json").scene);
  const kit::TabletopModel mg(scene, g), mf(scene, f);
  CHECK(mg.semantics().evidence_db(mg.outcome(), mg.block_scene().names()) ==
        mf.semantics().evidence_db(mf.outcome(), mf.block_scene().names()));
}

TEST_CASE("scene.decisions must name unary query predicates over the objects") {
  blk::Binding b = ksm_binding();
  b.outputs[0].false_est = gen::kPred_contact;  // an evidence predicate of arity 2
  const std::string e = binding_error(b);
  CHECK(e.find("domains/tabletop.ksm") != std::string::npos);
  CHECK(e.find("contact") != std::string::npos);
  b.outputs[0].false_est = 999;
  CHECK(binding_error(b).find("names no predicate") != std::string::npos);
}

TEST_CASE("kernels need pose.perturb sources; the schedule names declared kernels") {
  blk::Binding b = ksm_binding();
  b.kernels[0].sources.clear();
  CHECK(binding_error(b).find("kernel refine") != std::string::npos);
  blk::Binding renamed = ksm_binding();
  renamed.kernels[0].name = renamed.kernels[0].reverse = "jiggle";
  renamed.kernels.resize(1);
  renamed.schedule[0].probabilities = {{"jiggle", 1.0}};
  auto scene = std::make_shared<const ksmc::stdlib::tabletop::Scene>();
  const kit::KitSetup k = kit::make_setup(renamed, scene);  // a kernel's name is the author's choice
  REQUIRE(k.setup.kernels.size() == 1);
  CHECK(k.setup.kernels[0]->name() == "jiggle");
  blk::Binding unknown = ksm_binding();
  unknown.schedule[0].probabilities = {{"nudge", 1.0}};
  CHECK_THROWS_AS(kit::make_setup(unknown, scene), rd::ConfigError);
}

TEST_CASE("several sources of one kernel: each move uses one of them") {
  blk::Binding b = ksm_binding();
  b.kernels[0].sources.push_back(blk::pose::perturb(0.005, 0.02, 5));
  const kit::RefineKernel k(b.kernels[0], true);
  CHECK(k.sources().size() == 2);
  CHECK(k.sources()[1].candidates == 5);
}

TEST_CASE("pose.fit kernel: exact independence densities, runs beside refine") {
  blk::Binding b = ksm_binding();
  REQUIRE(b.kernels.at(0).name == "refine");
  b.kernels.resize(1);
  b.kernels.push_back({"fit", "fit", blk::Move::fit, {blk::pose::fit(0.5, 0.0)}, "kernel fit(o) reverse fit = pose.fit(...)"});
  b.schedule[0].probabilities = {{"refine", 0.5}, {"fit", 0.5}};
  // A fit kernel with a perturb source (or the reverse) is refused.
  blk::Binding wrong = b;
  wrong.kernels[1].sources = {blk::pose::perturb(0.001, 0.01, 5)};
  CHECK(binding_error(wrong).find("pose.fit") != std::string::npos);
  blk::Binding mixed = b;
  mixed.kernels[0].sources.push_back(blk::pose::fit(1.0, 0.0));
  CHECK(binding_error(mixed).find("pose.perturb") != std::string::npos);

  const auto scene = std::make_shared<const ksmc::stdlib::tabletop::Scene>(
      ksmc::stdlib::tabletop::load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json").scene);
  kit::TabletopModel model(scene, b);
  const kit::FitKernel k(b.kernels[1], b.likelihood.estimate_sigma_t, b.likelihood.estimate_sigma_r);
  ksmc::runtime::mcmc::Rng rng(7);
  const auto before = model.scene().objects;
  const auto p = k.propose(model, rng);
  REQUIRE(model.in_move());
  std::size_t moved = before.size();
  for (std::size_t i = 0; i < before.size(); ++i)
    if (!(model.scene().objects[i].pose.t - before[i].pose.t).isZero()) moved = i;
  REQUIRE(moved < before.size());
  const auto& fit = model.block_scene().fit(blk::Scene::body_of_object(moved));
  const double pick = -std::log(static_cast<double>(model.observed_objects().size()));
  CHECK(p.log_q_fwd == Approx(ksmc::stdlib::tabletop::fit_log_density(fit, 0.5, model.scene().objects[moved].pose) + pick));
  CHECK(p.log_q_bwd == Approx(ksmc::stdlib::tabletop::fit_log_density(fit, 0.5, before[moved].pose) + pick));
  model.reject();
  // The chain runs with both kernels.
  const auto r = ksmc::tests::tabletop_kit::run_kit(b, scene, 50, 3);
  CHECK(r.probabilities.size() == scene->objects.size());
}
