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
#include "tests/tabletop_kit/e2e_support.h"
#include "tools/tabletop_families/families.h"

namespace ksmc::tests::tabletop_kit {

namespace tf = ksmc::tools::tabletop_families;
namespace sim = ksmc::tools::tabletop_sim;

struct FamilyScore {
  std::string family;
  long scenes = 0;
  Score score;
  std::map<std::string, Counts> false_by_kind;  // recall of false estimates per generator kind
  double undecided_percent() const {
    return score.positives == 0 ? 0.0 : 100.0 * static_cast<double>(score.positive_undecided) / static_cast<double>(score.positives);
  }
};

struct FamilyRun {
  std::uint64_t seed = 2027;       // batch seed (scene seeds: tf::family_scene_seed)
  long scenes = 12;
  std::uint64_t iterations = 300;  // sampler iterations per scene (tabletop_family_eval: the binary's default)
  kit::KitOptions options;
};

inline FamilyScore evaluate_family(const tf::Family& family, const blk::Binding& binding, const FamilyRun& run) {
  FamilyScore fs;
  fs.family = std::string(family.name);
  for (long i = 0; i < run.scenes; ++i) {
    const auto g = tf::generate(family, tf::family_scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    const std::string name = fmt::format("{}/scene_{:03}.json", family.name, i);
    auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(g)), name, ".");
    auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
    const tt::TabletopResult r = run_kit(binding, scene, run.iterations, 1 + static_cast<std::uint64_t>(i), run.options);
    score(r, nlohmann::json::parse(sim::truth_json(g)), fs.score);
    for (const auto& o : g.objects) {
      if (o.false_kind == sim::FalseKind::none) continue;
      const int k = r.scene.find(o.id);
      const auto decided = tt::decide(r.probabilities[static_cast<std::size_t>(k)].false_prob);
      fs.false_by_kind[std::string(sim::to_string(o.false_kind))].add(decided.value_or(false), true);
    }
    ++fs.scenes;
  }
  return fs;
}

// Training worlds for `ksmc learn` (docs/mln.md): per scene of `family`, the evidence the
// kit extracts at the input poses (Alchemy .db, closed world) and the true query atoms —
// falseEst, hidden from the truth; supported(o) / supportive(o), which hard rule r10 and the
// closed-world rule r17 derive from the evidence, as the upper / lower body of a support
// edge of that evidence (the table included). Writes DIR/<family>_<i>.db; returns the
// number written.
inline long write_training_dbs(const tf::Family& family, const blk::Binding& binding, const FamilyRun& run,
                               const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  long written = 0;
  for (long i = 0; i < run.scenes; ++i) {
    const auto g = tf::generate(family, tf::family_scene_seed(family, run.seed, static_cast<std::uint64_t>(i)));
    auto load = tt::parse_scene(nlohmann::json::parse(sim::scene_json(g)), "scene.json", ".");
    auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
    kit::KitSetup k = kit::make_setup(binding, scene);
    const auto model = k.setup.model_factory(0);
    std::string db = kit::evidence_db_of(static_cast<const kit::TabletopModel&>(*model));
    db += "// true query atoms (generator truth; unlisted: false)\n";
    for (const auto& o : g.objects) {
      if (o.false_kind != sim::FalseKind::none) db += "falseEst(" + o.id + ")\n";
      if (o.hidden) db += "hidden(" + o.id + ")\n";
    }
    std::set<std::string> upper, lower;
    for (const auto& [u, l] : tt::support_edges(kit::result_of(static_cast<const kit::TabletopModel&>(*model)).evidence))
      upper.insert(u), lower.insert(l);
    for (const auto& u : upper) db += "supported(" + u + ")\n";
    for (const auto& l : lower) db += "supportive(" + l + ")\n";
    std::ofstream(dir / fmt::format("{}_{:03}.db", family.name, i)) << db;
    ++written;
  }
  return written;
}

inline std::string prf(const Counts& c) {
  return fmt::format("{:.2f} {:.2f} {:.2f}", c.precision(), c.recall(), c.f1());
}

inline std::string family_table(const std::vector<FamilyScore>& rows) {
  std::string out =
      "| family      | scenes | objects | false n | false P R F1   | hidden n | hidden P R F1  | support n | support P R F1 | contact n | contact P R F1 | undecided % |\n"
      "|-------------|-------:|--------:|--------:|----------------|---------:|----------------|----------:|----------------|----------:|----------------|------------:|\n";
  for (const auto& r : rows) {
    const Score& s = r.score;
    out += fmt::format("| {:<11} | {:>6} | {:>7} | {:>7} | {:<14} | {:>8} | {:<14} | {:>9} | {:<14} | {:>9} | {:<14} | {:>11.1f} |\n",
                       r.family, r.scenes, s.objects, s.is_false.tp + s.is_false.fn, prf(s.is_false),
                       s.is_hidden.tp + s.is_hidden.fn, prf(s.is_hidden), s.support.tp + s.support.fn, prf(s.support),
                       s.contact.tp + s.contact.fn, prf(s.contact), r.undecided_percent());
  }
  return out;
}

// One line per family: recall of each false-estimate kind (found / generated).
inline std::string false_kind_lines(const std::vector<FamilyScore>& rows) {
  std::string out;
  for (const auto& r : rows) {
    out += fmt::format("{:<11} false kinds found:", r.family);
    for (const auto& [kind, c] : r.false_by_kind) out += fmt::format(" {} {}/{}", kind, c.tp, c.tp + c.fn);
    out += "\n";
  }
  return out;
}

}  // namespace ksmc::tests::tabletop_kit
