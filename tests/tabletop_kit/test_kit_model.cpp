// The table-top model: incremental evidence equals full extraction, the MLN is re-run only
// when the evidence bits change, reject restores the state exactly, the prior is the exact
// log Z of the evidence, and the kit's likelihood is eq. 4.4.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>

#include "runtime/mln/grounder.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/log_z.h"
#include "runtime/mcmc/rng.h"
#include "stdlib/tabletop/kit/kit_likelihood.h"
#include "stdlib/tabletop/kit/refine_kernel.h"
#include "stdlib/tabletop/kit/tabletop_model.h"
#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/pose_proposal.h"
#include "stdlib/tabletop/rng.h"
#include "stdlib/tabletop/scene_io.h"
#include "tests/tabletop_kit/binding.h"
#include "tests/tabletop_kit/config_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace tt = ksmc::stdlib::tabletop;
using namespace ksmc::tests::tabletop_kit;

namespace {

std::shared_ptr<const tt::Scene> example(const char* name) {
  return std::make_shared<const tt::Scene>(
      tt::load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop" / name).scene);
}

std::shared_ptr<const kit::KitConfig> config(const Tolerances& t = {}) {
  return std::make_shared<const kit::KitConfig>(kit::read_kit_config(tabletop_config(t)));
}

// A random pose near `p`: up to several cm and tens of degrees, so relations flip.
tt::Pose jump(const tt::Pose& p, std::mt19937_64& rng) {
  return tt::perturb_pose(p, 0.02, 0.3, rng);
}

}  // namespace

TEST_CASE("MLN evaluator re-runs only when the evidence bits change") {
  const auto scene = example("seed_example.json");
  const auto cfg = config();
  const tt::Evidence ev = tt::extract_evidence(*scene, cfg->evidence);
  std::vector<std::string> ids = ev.ids;
  kit::MlnEvaluator m(tabletop_binding(), ids);
  const auto a = m.evaluate(ev);
  CHECK(m.stats().runs == 1);
  const auto b = m.evaluate(ev);
  CHECK(m.stats().runs == 1);
  CHECK(m.stats().hits == 1);
  CHECK(a.get() == b.get());
  tt::Evidence changed = ev;
  changed.hover[1] = !changed.hover[1];
  const auto c = m.evaluate(changed);
  CHECK(m.stats().runs == 2);
  CHECK(c->log_z != a->log_z);
  (void)m.evaluate(ev);
  (void)m.evaluate(changed);
  CHECK(m.stats().runs == 2);
  CHECK(m.stats().lookups == 5);
}

TEST_CASE("LRU eviction keeps results identical") {
  const auto scene = example("seed_example.json");
  const auto cfg = config();
  const tt::Evidence ev = tt::extract_evidence(*scene, cfg->evidence);
  kit::MlnEvaluator small(tabletop_binding(), ev.ids, 2);
  kit::MlnEvaluator big(tabletop_binding(), ev.ids, 100);
  std::vector<tt::Evidence> evs(4, ev);
  for (std::size_t i = 1; i < 4; ++i) evs[i].hover[i] = !evs[i].hover[i];
  for (int round = 0; round < 3; ++round)
    for (const auto& e : evs) CHECK(small.evaluate(e)->log_z == big.evaluate(e)->log_z);
  CHECK(big.stats().runs == 4);
  CHECK(small.stats().runs == 12);  // capacity 2 < 4 distinct keys, cycled: every lookup misses
}

TEST_CASE("model moves re-use the MLN result when evidence is unchanged") {
  const auto scene = example("stack.json");
  kit::TabletopModel model(scene, config(), tabletop_binding());
  CHECK(model.mln().stats().runs == 1);
  // A 1 µm shift changes no relation.
  tt::Pose p = model.scene().objects[0].pose;
  p.t.x() += 1e-6;
  model.begin_move(0, p, std::nan(""));
  model.accept();
  CHECK(model.mln().stats().runs == 1);
  // Lifting an object 20 cm makes it hover: new evidence, one run.
  p.t.z() += 0.2;
  model.begin_move(0, p, std::nan(""));
  CHECK(model.mln().stats().runs == 2);
  model.reject();
  model.begin_move(0, p, std::nan(""));
  CHECK(model.mln().stats().runs == 2);  // cached
  model.reject();
}

TEST_CASE("incremental evidence equals full extraction along a random walk") {
  for (const char* name : {"seed_example.json", "stack.json", "single_level.json"}) {
    const auto scene = example(name);
    const auto cfg = config(recommended_tolerances());
    kit::TabletopModel model(scene, cfg, tabletop_binding());
    std::mt19937_64 rng(7);
    int flips = 0;
    std::vector<std::uint8_t> last = model.mln().key(model.evidence());
    for (int step = 0; step < 150; ++step) {
      const std::size_t i = rng() % model.scene().objects.size();
      model.begin_move(i, jump(model.scene().objects[i].pose, rng), std::nan(""));
      const tt::Evidence full = tt::extract_evidence(model.scene(), cfg->evidence);
      REQUIRE(model.evidence().atoms() == full.atoms());
      REQUIRE(model.mln().key(model.evidence()) == model.mln().key(full));
      if (rng() % 2) model.accept(); else model.reject();
      const tt::Evidence after = tt::extract_evidence(model.scene(), cfg->evidence);
      REQUIRE(model.evidence().atoms() == after.atoms());
      const auto now = model.mln().key(model.evidence());
      if (now != last) ++flips;
      last = now;
    }
    INFO(name);
    CHECK(flips > 10);  // the walk really changed relations
  }
}

TEST_CASE("reject restores the log terms bit for bit; snapshot round-trips") {
  const auto scene = example("seed_example.json");
  kit::TabletopModel model(scene, config(), tabletop_binding());
  kit::RefineKernel kernel(kit::read_kit_config(tabletop_config()).kernels[0]);
  ksmc::runtime::mcmc::Rng rng(3);
  for (int step = 0; step < 100; ++step) {
    const double ll = model.log_likelihood(), lp = model.log_prior();
    const auto snap = model.snapshot();
    const auto p = kernel.propose(model, rng);
    if (p.was_declined()) continue;
    CHECK(std::isfinite(p.log_q_fwd));
    if (step % 3 == 0) {
      model.accept();
    } else {
      model.reject();
      REQUIRE(model.log_likelihood() == ll);
      REQUIRE(model.log_prior() == lp);
      REQUIRE(model.snapshot() == snap);
    }
  }
  kit::TabletopModel other(scene, config(), tabletop_binding());
  other.restore(model.snapshot());
  CHECK(other.log_likelihood() == Approx(model.log_likelihood()).epsilon(1e-12));
  CHECK(other.log_prior() == model.log_prior());
  CHECK(other.snapshot() == model.snapshot());
}

TEST_CASE("refine: the current pose competes, so an accepted move never lowers the likelihood") {
  const auto scene = example("seed_example.json");
  for (const bool competes : {true, false}) {
    kit::TabletopModel model(scene, config(), tabletop_binding());
    auto kc = kit::read_kit_config(tabletop_config()).kernels[0];
    kc.current_competes = competes;
    kit::RefineKernel kernel(kc);
    ksmc::runtime::mcmc::Rng rng(5);
    int declined = 0, lowered = 0;
    for (int step = 0; step < 300; ++step) {
      const double ll = model.log_likelihood();
      const auto p = kernel.propose(model, rng);
      if (p.was_declined()) {
        ++declined;
        continue;
      }
      if (model.log_likelihood() < ll) ++lowered;
      model.accept();  // keep every proposal: the ascent alone
    }
    INFO("current_competes " << competes);
    if (competes) {
      CHECK(lowered == 0);
      CHECK(declined > 0);  // near the optimum e_{t,0} often has the best weight
    } else {
      CHECK(lowered > 0);   // the best new candidate can be worse than the current pose
      CHECK(declined == 0);
    }
  }
}

TEST_CASE("prior mln is the log-weight of the most probable world given the evidence (log Z kept)") {
  const auto scene = example("seed_example.json");
  const auto cfg = config();
  kit::TabletopModel model(scene, cfg, tabletop_binding());
  namespace mln = ksmc::runtime::mln;
  const auto& program = ksmc_generated::tabletop::program();
  mln::Domain domain = ksmc_generated::tabletop::make_domain();
  const tt::Evidence& ev = model.evidence();
  for (const auto& id : ev.ids) domain.add(ksmc_generated::tabletop::kType_object, id);
  mln::Evidence e(program, domain);
  e.clear();
  // Closed world: every evidence atom false, then the true ones from the atom list.
  for (std::int32_t p = 0; p < static_cast<std::int32_t>(program.predicates.size()); ++p)
    if (!program.predicates[p].query)
      for (std::int64_t f = 0; f < e.num_atoms(p); ++f) e.set_flat(p, f, 0);
  for (const auto& atom : ev.atoms()) {
    std::vector<std::int32_t> args;
    for (const auto& a : atom.args) args.push_back(*domain.find(ksmc_generated::tabletop::kType_object, a));
    e.set(*program.find_predicate(atom.predicate), args, true);
  }
  const mln::Grounding g = mln::ground(program, domain, e);  // the generic grounder
  const mln::LogZResult z = mln::log_partition(g.network);
  REQUIRE(z.exact);
  const mln::MapResult map = mln::exact_map(g.network);
  REQUIRE(map.feasible);
  // Default quantity: eq. 4.3 for the world (evidence, most probable query atoms).
  CHECK(model.log_prior() == Approx(map.log_weight).epsilon(1e-12));
  CHECK(model.mln_outcome().log_map == Approx(map.log_weight).epsilon(1e-12));
  CHECK(model.mln_outcome().log_z == Approx(z.log_z).epsilon(1e-12));
  CHECK(map.log_weight < z.log_z);  // one world of the sum
  // The log Z reading is still selectable.
  auto lz = std::make_shared<kit::KitConfig>(*cfg);
  lz->prior_quantity = kit::PriorQuantity::log_z;
  kit::TabletopModel model_z(scene, lz, tabletop_binding());
  CHECK(model_z.log_prior() == Approx(z.log_z).epsilon(1e-12));
}

TEST_CASE("kit likelihood is eq. 4.4; the robust variant caps residuals at outlier_px") {
  const auto scene = example("seed_example.json");
  kit::KeypointModel plain;
  tt::KeypointLikelihoodParams lib;
  for (const auto& o : scene->objects)
    CHECK(kit::object_log_likelihood(*scene, o, o.pose, plain) ==
          Approx(tt::keypoint_log_likelihood(*scene, o, o.pose, lib)).epsilon(1e-12));
  // Shift one object 5 cm: plain likelihood drops quadratically, robust stays bounded.
  const auto& o = scene->objects[0];
  tt::Pose far = o.pose;
  far.t.x() += 0.5;
  kit::KeypointModel robust{1.0, true, 20.0};
  const double lr = kit::object_log_likelihood(*scene, o, far, robust);
  const double lp = kit::object_log_likelihood(*scene, o, far, plain);
  const double norm = -std::log(2.0 * 3.14159265358979323846);
  const double floor = static_cast<double>(o.keypoints_model.size()) * (norm - 200.0);
  CHECK(lp < lr);
  CHECK(lr >= floor - 1e-9);
}
