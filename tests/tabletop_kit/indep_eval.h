// Per-family evaluation of the table-top kit on the independent generator
// (tools/tabletop_indep): scenes the project's own generator did not make. Shared by
// `tabletop_family_eval --generator indep` and the test_tabletop_kit_indep CTest.
#pragma once

#include <algorithm>
#include <iostream>
#include <string>

#include "tests/tabletop_kit/family_eval.h"
#include "tests/tabletop_kit/family_score.h"
#include "tools/tabletop_indep/families.h"

namespace ksmc::tests::tabletop_kit {

namespace ti = ksmc::tools::tabletop_indep;

inline FamilyScore evaluate_indep_family(const ti::Family& family, const blk::Binding& binding, const FamilyRun& run) {
  FamilyScore fs;
  fs.family = std::string(family.name);
  for (long i = 0; i < run.scenes; ++i) {
    const ti::IndepScene g = ti::generate(family, ti::scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    const std::string name = fmt::format("{}/scene_{:03}.json", family.name, i);
    const nlohmann::json truth = nlohmann::json::parse(g.truth_json());
    const tt::TabletopResult r = add_scene(fs, binding, g.scene_json(), truth, name, run, i);
    for (const auto& t : truth.at("objects")) {
      const int k = r.scene.find(truth_id(t.at("id")));
      const auto& p = r.probabilities[static_cast<std::size_t>(k)];
      const bool is_false = t.at("false").get<bool>(), is_hidden = t.at("hidden").get<bool>();
      if (is_false) fs.false_by_kind[t.at("kind").get<std::string>()].add(tt::decide(p.false_prob).value_or(false), true);
      if (run.verbose && (is_false != tt::decide(p.false_prob).value_or(false) || is_hidden != tt::decide(p.hidden_prob).value_or(false))) {
        const ti::Estimate& e = *std::find_if(g.estimates.begin(), g.estimates.end(), [&](const auto& x) { return x.id == truth_id(t.at("id")); });
        std::cerr << fmt::format("{} {}: {} hidden={} P(false) {:.2f} P(hidden) {:.2f}; bottom {:.1f} mm, tilt {:.1f} deg, {} keypoints\n",
                                 name, e.id, t.at("kind").get<std::string>(), is_hidden, p.false_prob, p.hidden_prob,
                                 1e3 * e.clean.bottom(), e.clean.tilt() * 57.2958, e.kp_model.size());
      }
    }
  }
  return fs;
}

// training_db (family_eval.h) of each scene of an independent `family`, written to
// DIR/<family>_<i>.db; returns the number written.
inline long write_indep_training_dbs(const ti::Family& family, const blk::Binding& binding, const FamilyRun& run,
                                     const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (long i = 0; i < run.scenes; ++i) {
    const ti::IndepScene g = ti::generate(family, ti::scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    std::ofstream(dir / fmt::format("{}_{:03}.db", family.name, i))
        << training_db(binding, g.scene_json(), nlohmann::json::parse(g.truth_json()));
  }
  return run.scenes;
}

}  // namespace ksmc::tests::tabletop_kit
