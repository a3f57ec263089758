// End to end on physics-generated scenes (tools/tabletop_sim) and on the real HOPE frame:
// the kit's sampler + MLN against the generator's truth.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <iostream>

#include "stdlib/tabletop/hope_import.h"
#include "stdlib/tabletop/scene_io.h"
#include "tools/tabletop_sim/generator.h"
#include "tools/tabletop_sim/scene_writer.h"
#include "tests/support/shared_data.h"
#include "tests/tabletop_kit/e2e_support.h"

using namespace ksmc::tests::tabletop_kit;
namespace sim = ksmc::tools::tabletop_sim;

namespace {

constexpr int kScenes = 50;
std::uint64_t iterations() {
  const char* env = std::getenv("KSMC_TTKIT_ITERATIONS");  // for calibration runs
  return env ? std::strtoull(env, nullptr, 10) : 300;
}

struct Generated {
  std::shared_ptr<const tt::Scene> scene;
  nlohmann::json truth;
};

const std::vector<Generated>& scenes() {
  static const std::vector<Generated> all = [] {
    std::vector<Generated> v;
    sim::GeneratorOptions opt;
    for (int i = 0; i < kScenes; ++i) {
      const auto g = sim::generate_scene(sim::scene_seed(2026, static_cast<std::uint64_t>(i)), opt);
      const std::string name = fmt::format("scene_{:03}.json", i);
      auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(g)), name, ".");
      v.push_back({std::make_shared<const tt::Scene>(std::move(load.scene)), nlohmann::json::parse(sim::truth_json(g))});
    }
    return v;
  }();
  return all;
}

Score run_all(const blk::Binding& binding, std::uint64_t iters, kit::KitOptions options = {}) {
  Score s;
  for (std::size_t i = 0; i < scenes().size(); ++i)
    score(run_kit(binding, scenes()[i].scene, iters, 1 + i, options), scenes()[i].truth, s);
  return s;
}

}  // namespace

TEST_CASE("50 generated scenes: false / hidden / support accuracy") {
  long objects = 0, n_false = 0, n_hidden = 0;
  for (const auto& g : scenes()) {
    objects += static_cast<long>(g.scene->objects.size());
    for (const auto& o : g.truth["objects"]) {
      n_false += o["false"].get<bool>();
      n_hidden += o["hidden"].get<bool>();
    }
  }
  std::cout << fmt::format("{} scenes, {} objects ({} false, {} hidden), {} iterations per scene\n", kScenes,
                           objects, n_false, n_hidden, iterations());
  REQUIRE(n_false > 10);
  REQUIRE(n_hidden > 10);

  kit::KitOptions seed_sampler;
  seed_sampler.prior_quantity = kit::PriorQuantity::log_z;
  seed_sampler.current_competes = false;
  const Score seed = run_all(seed_binding(), iterations(), seed_sampler);
  std::cout << "seed values (3 deg, 4 mm, 4 mm, plain Gaussian), log Z prior, best new candidate always, best state:\n"
            << table(seed);
  const Score initial = run_all(ksm_binding(), 0);
  std::cout << "domains/tabletop.ksm, input poses (0 iterations):\n" << table(initial);
  const Score ksm = run_all(ksm_binding(), iterations());
  std::cout << "domains/tabletop.ksm (MAP-world prior, current pose competes), best state:\n" << table(ksm);

  // Targets: false F1 >= 0.95, hidden F1 >= 0.9. Asserted: what the kit reaches on these 50
  // scenes (seed 2026), with a small margin. docs/tabletop_kit.md lists every remaining
  // miss (intersecting pairs that no evidence orders, truth the estimate contradicts).
  if (iterations() == 300) {
    CHECK(initial.is_false.f1() >= 0.93);   // measured 0.961
    CHECK(initial.is_hidden.f1() >= 0.95);  // 0.961
    CHECK(initial.support.f1() >= 0.98);    // 0.999
    CHECK(ksm.is_false.f1() >= 0.93);       // 0.940 (target 0.95: missed, see docs)
    CHECK(ksm.is_hidden.f1() >= 0.955);     // 0.967 (target 0.9: reached)
    CHECK(ksm.support.f1() >= 0.98);        // 0.994
    CHECK(ksm.undecided <= 15);             // 8
    CHECK(ksm.support.f1() > seed.support.f1());
    CHECK(ksm.is_false.f1() > seed.is_false.f1());
  }
}

TEST_CASE("HOPE video frame: nothing false or hidden, everything on the table") {
  const std::string rel = "data/tabletop/hope_video_frame/meta_data.json";
  if (!ksmc::tests::have_shared(rel)) return;
  const auto hope = tt::import_hope_file(ksmc::tests::shared_dir() / rel);
  const auto scene = std::make_shared<const tt::Scene>(hope.scene);
  for (const auto& [label, binding] : {std::pair<const char*, const blk::Binding*>{"seed values", &seed_binding()},
                                       std::pair<const char*, const blk::Binding*>{"domains/tabletop.ksm", &ksm_binding()}}) {
    const tt::TabletopResult r = run_kit(*binding, scene, 500, 1);
    const auto sup = tt::support_edges(r);
    int reported_false = 0, reported_hidden = 0, on_table = 0;
    for (std::size_t i = 0; i < r.scene.objects.size(); ++i) {
      reported_false += tt::decide(r.probabilities[i].false_prob).value_or(false);
      reported_hidden += tt::decide(r.probabilities[i].hidden_prob).value_or(false);
      for (const auto& e : sup) on_table += (e.first == r.scene.objects[i].id && e.second == "table");
    }
    std::cout << fmt::format("HOPE ({}): {} objects, {} false, {} hidden, {} supported by the table, {} support edges\n",
                             label, r.scene.objects.size(), reported_false, reported_hidden, on_table, sup.size());
    if (std::string(label) == "domains/tabletop.ksm") {
      CHECK(reported_false == 0);
      CHECK(reported_hidden == 0);
      CHECK(on_table == static_cast<int>(r.scene.objects.size()));
      CHECK(sup.size() == r.scene.objects.size());
    }
  }
}
