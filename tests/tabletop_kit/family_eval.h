// Per-family evaluation of the table-top kit on the noise-model families of
// tools/tabletop_families: generate a family's scenes, run the kit's sampler on each, score
// false / hidden / support / contact against the generator's truth. Shared by the
// tabletop_family_eval driver and the test_tabletop_kit_families CTest.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "stdlib/tabletop/scene_io.h"
#include "tools/tabletop_sim/scene_writer.h"
#include "tests/tabletop_kit/family_score.h"
#include "tools/tabletop_families/families.h"

namespace ksmc::tests::tabletop_kit {

namespace tf = ksmc::tools::tabletop_families;
namespace sim = ksmc::tools::tabletop_sim;

inline FamilyScore evaluate_family(const tf::Family& family, const blk::Binding& binding, const FamilyRun& run) {
  FamilyScore fs;
  fs.family = std::string(family.name);
  for (long i = 0; i < run.scenes; ++i) {
    const auto g = tf::generate(family, tf::family_scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    const std::string name = fmt::format("{}/scene_{:03}.json", family.name, i);
    const tt::TabletopResult r = add_scene(fs, binding, sim::scene_json(g), nlohmann::json::parse(sim::truth_json(g)), name, run, i);
    for (const auto& o : g.objects) {
      if (o.false_kind == sim::FalseKind::none) continue;
      const int k = r.scene.find(o.id);
      const auto decided = tt::decide(r.probabilities[static_cast<std::size_t>(k)].false_prob);
      fs.false_by_kind[std::string(sim::to_string(o.false_kind))].add(decided.value_or(false), true);
    }
  }
  return fs;
}

// A training world for `ksmc learn` (docs/mln.md): the evidence the kit extracts at the input
// poses of `scene_json` (Alchemy .db, closed world) and the true query atoms: falseEst, hidden
// from `truth` (either generator's truth.json: objects with id, false, hidden);
// supported(o) / supportive(o), which hard rule r10 and the closed-world rule r17 derive from
// the evidence, as the upper / lower body of a support edge of that evidence (the table
// included).
inline std::string training_db(const blk::Binding& binding, const std::string& scene_json, const nlohmann::json& truth) {
  auto load = tt::parse_scene(nlohmann::json::parse(scene_json), "scene.json", ".");
  auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
  kit::KitSetup k = kit::make_setup(binding, scene);
  const auto model = k.setup.model_factory(0);
  const auto& m = static_cast<const kit::TabletopModel&>(*model);
  std::string db = kit::evidence_db_of(m);
  db += "// true query atoms (generator truth; unlisted: false)\n";
  for (const auto& o : truth.at("objects")) {
    if (o.at("false").get<bool>()) db += "falseEst(" + truth_id(o.at("id")) + ")\n";
    if (o.at("hidden").get<bool>()) db += "hidden(" + truth_id(o.at("id")) + ")\n";
  }
  std::set<std::string> upper, lower;
  for (const auto& [u, l] : tt::support_edges(kit::result_of(m).evidence)) upper.insert(u), lower.insert(l);
  for (const auto& u : upper) db += "supported(" + u + ")\n";
  for (const auto& l : lower) db += "supportive(" + l + ")\n";
  return db;
}

// training_db of each scene of `family`, written to DIR/<family>_<i>.db; returns the number
// written.
inline long write_training_dbs(const tf::Family& family, const blk::Binding& binding, const FamilyRun& run,
                               const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (long i = 0; i < run.scenes; ++i) {
    const auto g = tf::generate(family, tf::family_scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    std::ofstream(dir / fmt::format("{}_{:03}.db", family.name, i))
        << training_db(binding, sim::scene_json(g), nlohmann::json::parse(sim::truth_json(g)));
  }
  return run.scenes;
}

}  // namespace ksmc::tests::tabletop_kit
