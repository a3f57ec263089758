// Per-family scores of the table-top kit and their tables, shared by the evaluations on the
// families of tools/tabletop_families (family_eval.h) and of the independent generator
// tools/tabletop_indep (indep_eval.h).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "stdlib/tabletop/scene_io.h"
#include "tests/tabletop_kit/e2e_support.h"

namespace ksmc::tests::tabletop_kit {

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
  bool verbose = false;            // print each missed or wrongly claimed false / hidden object (stderr)
};

// Runs the kit on one scene (JSON text; `name` for messages), scores it against `truth`
// into `fs` and returns the result. The chain's seed is 1 + the scene's index.
inline tt::TabletopResult add_scene(FamilyScore& fs, const blk::Binding& binding, const std::string& scene_text,
                                    const nlohmann::json& truth, const std::string& name, const FamilyRun& run, long index) {
  auto load = tt::parse_scene(nlohmann::json::parse(scene_text), name, ".");
  auto scene = std::make_shared<const tt::Scene>(std::move(load.scene));
  tt::TabletopResult r = run_kit(binding, scene, run.iterations, 1 + static_cast<std::uint64_t>(index), run.options);
  score(r, truth, fs.score);
  ++fs.scenes;
  return r;
}

inline std::string prf(const Counts& c) {
  return fmt::format("{:.2f} {:.2f} {:.2f}", c.precision(), c.recall(), c.f1());
}

inline std::string family_table(const std::vector<FamilyScore>& rows) {
  std::string out =
      "| family            | scenes | objects | false n | false P R F1   | hidden n | hidden P R F1  | support n | support P R F1 | contact n | contact P R F1 | undecided % |\n"
      "|-------------------|-------:|--------:|--------:|----------------|---------:|----------------|----------:|----------------|----------:|----------------|------------:|\n";
  for (const auto& r : rows) {
    const Score& s = r.score;
    out += fmt::format("| {:<17} | {:>6} | {:>7} | {:>7} | {:<14} | {:>8} | {:<14} | {:>9} | {:<14} | {:>9} | {:<14} | {:>11.1f} |\n",
                       r.family, r.scenes, s.objects, s.is_false.tp + s.is_false.fn, prf(s.is_false),
                       s.is_hidden.tp + s.is_hidden.fn, prf(s.is_hidden), s.support.tp + s.support.fn, prf(s.support),
                       s.contact.tp + s.contact.fn, prf(s.contact), r.undecided_percent());
  }
  return out;
}

// The families' counts summed: the pooled figures, exact (the table's rows round to two
// decimals). One line, read by scripts/tabletop_weight_search.py:
//   pooled over 9 families: false P R F1 0.943 0.781 0.854 (tp 232 fp 14 fn 65) | hidden ... | undecided 3.7 %
inline std::string pooled_line(const std::vector<FamilyScore>& rows) {
  FamilyScore all;
  for (const auto& r : rows) all.score += r.score;
  auto part = [](std::string_view name, const Counts& c) {
    return fmt::format("{} P R F1 {:.3f} {:.3f} {:.3f} (tp {} fp {} fn {})", name, c.precision(), c.recall(), c.f1(), c.tp,
                       c.fp, c.fn);
  };
  const Score& s = all.score;
  return fmt::format("pooled over {} families: {} | {} | {} | {} | undecided {:.1f} % of {} positives\n", rows.size(),
                     part("false", s.is_false), part("hidden", s.is_hidden), part("support", s.support),
                     part("contact", s.contact), all.undecided_percent(), s.positives);
}

// One line per family: recall of each false-estimate kind (found / generated).
inline std::string false_kind_lines(const std::vector<FamilyScore>& rows) {
  std::string out;
  for (const auto& r : rows) {
    out += fmt::format("{:<17} false kinds found:", r.family);
    for (const auto& [kind, c] : r.false_by_kind) out += fmt::format(" {} {}/{}", kind, c.tp, c.tp + c.fn);
    out += "\n";
  }
  return out;
}

}  // namespace ksmc::tests::tabletop_kit
