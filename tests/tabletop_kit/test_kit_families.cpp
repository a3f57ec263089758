// The noise-model families (tools/tabletop_families) and the kit's accuracy on each of them
// (issue 12). The generator cases are fast; the accuracy case runs every family (30 scenes,
// 300 iterations each, about 100 s) and asserts each family's figures: the targets
// where the kit reaches them, otherwise the measured value with a small margin — the gap to
// the target is listed in docs/tabletop_families.md.
#include <catch2/catch.hpp>

#include <iostream>
#include <set>

#include "tests/tabletop_kit/family_floors.h"
#include "tests/tabletop_kit/family_eval.h"

using namespace ksmc::tests::tabletop_kit;

namespace {

// Generated scene of family `name`, index i, batch seed 11.
sim::GeneratedScene scene_of(const char* name, std::uint64_t i) {
  const auto& f = tf::family(name);
  return tf::generate(f, tf::family_scene_seed(f, 11, i));
}

}  // namespace

TEST_CASE("families: known names, deterministic scenes, disjoint seeds") {
  REQUIRE(tf::families().size() == 9);
  CHECK_THROWS_WITH(tf::family("nope"), Catch::Contains("unknown family 'nope'") && Catch::Contains("pose_noise"));
  CHECK(sim::scene_json(scene_of("pose_noise", 0)) == sim::scene_json(scene_of("pose_noise", 0)));
  CHECK(tf::family_scene_seed(tf::family("base"), 1, 0) != tf::family_scene_seed(tf::family("camera"), 1, 0));
  CHECK(tf::family_scene_seed(tf::family("base"), 1, 0) != tf::family_scene_seed(tf::family("base"), 1, 1));
}

TEST_CASE("families: each family brings what it varies") {
  std::set<std::string> models, kinds;
  bool numeric = false, several_on_one = false;
  long leaning_contacts = 0;
  for (std::uint64_t i = 0; i < 6; ++i) {
    for (const auto& o : scene_of("catalogue", i).objects) models.insert(std::string(o.item.model));
    for (const auto& o : scene_of("false_kinds", i).objects) kinds.insert(std::string(sim::to_string(o.false_kind)));
    const auto m = scene_of("mixed", i);
    numeric = numeric || nlohmann::json::parse(sim::scene_json(m))["objects"][0]["id"].is_number();
    const auto h = scene_of("hidden", i);
    std::map<int, int> carried;  // physical supporter -> boxes on it
    for (const auto& [upper, lower] : h.relations.support)
      if (lower >= 0) several_on_one = several_on_one || ++carried[lower] >= 2;
    for (const auto& [a, b] : scene_of("leaning", i).contact) leaning_contacts += (a != b);
  }
  const bool wide = models.count("dice") + models.count("cube") + models.count("big_cube") + models.count("thin_board") +
                    models.count("cd_case") + models.count("matchbox") + models.count("shoe_box") + models.count("long_box");
  CHECK(wide);
  CHECK(kinds.count("shifted_copy") + kinds.count("duplicate") + kinds.count("wrong_size") + kinds.count("flipped") >= 3);
  CHECK(numeric);
  CHECK(several_on_one);
  CHECK(leaning_contacts >= 6);
}

TEST_CASE("families: false kinds are observably wrong") {
  sim::Rng rng(5);
  const sim::Box original{Eigen::Vector3d(0.10, 0.06, 0.03), sim::Pose{Eigen::Vector3d(0, 0, 0.015), Eigen::Quaterniond::Identity()}};
  const sim::FalseKindParams p;
  const auto copy = sim::shifted_copy(rng, original, p);
  REQUIRE(copy);
  CHECK(sim::sat_overlap(*copy, original) >= p.min_shift - 1e-6);
  CHECK(sim::sat_overlap(*copy, original) <= p.max_shift + 1e-6);
  const auto flip = sim::flipped(rng, original, p);
  REQUIRE(flip);
  CHECK(std::abs(sim::lowest_z(*flip) - sim::lowest_z(original)) >= 0.5 * p.min_flip_change - 1e-9);
  const auto sized = sim::wrong_size(rng, original, p);
  REQUIRE(sized);
  CHECK(std::abs(sized->size.z() - original.size.z()) >= p.min_size_error);
  // A cube cannot be flipped into anything observably different.
  const sim::Box cube{Eigen::Vector3d::Constant(0.05), original.pose};
  CHECK_FALSE(sim::flipped(rng, cube, p));
}

// Per family: the least false F1, hidden F1, support-edge F1 and the largest undecided share
// (% of the truly false or hidden objects) asserted. The targets (0.95 / 0.9 / 0.95 / 5 %)
// where the kit reaches them, otherwise the value measured at commit time less 0.03 (3
// points more undecided): docs/tabletop_families.md lists the gaps.
const Floor kFloors[] = {
    {"base", 0.92, 0.90, 0.95, 11.9},  // measured 0.949 / 0.95 / 0.99, 8.9 %
    {"pose_noise", 0.90, 0.90, 0.95, 9.8},  // measured 0.935 / 0.93 / 0.99, 6.8 %
    {"camera", 0.95, 0.90, 0.95, 6.4},  // measured 0.97 / 0.98 / 1.00, 3.4 %
    // keypoints, false_kinds: undecided floors raised with the pose-estimate term (KitOptions::
    // pose_sigma_*): at 300 iterations one more object each sits in [0.4, 0.6] while false F1
    // rises (0.86 -> 0.92, 0.70 -> 0.72); at the binary's 2000 iterations 3.0 % and 11.9 %
    // (docs/tabletop_families/iterations_and_estimate.md).
    // pose_noise, mixed: with r26 (snugger) at 300 iterations undecided rose 5.4 -> 6.8 % and
    // 6.9 -> 8.3 %, at 2000 iterations it fell (5.4 -> 4.1 %) and rose (9.7 -> 11.1 %)
    // (docs/tabletop_families/snugger_r26.md).
    {"keypoints", 0.95, 0.90, 0.95, 5.0},  // measured 0.98 / 0.97 / 1.00, 3.0 %
    {"catalogue", 0.88, 0.90, 0.95, 12.4},  // measured 0.91 / 0.93 / 0.97, 9.4 %
    {"false_kinds", 0.68, 0.87, 0.92, 17.4},  // measured 0.71 / 0.91 / 0.95, 10.2 %; with r28 and the engine's
                                              // per-term log a 0.80 / 0.90 / 0.96, 14.4 %
    {"hidden", 0.80, 0.90, 0.95, 5.0},  // measured 0.83 / 0.98 / 0.98, 3.1 %
    {"leaning", 0.95, 0.90, 0.95, 5.0},  // measured 1.00 / 0.99 / 0.99, 1.1 %
    {"mixed", 0.81, 0.84, 0.95, 11.3},  // measured 0.836 / 0.87 / 0.97, 8.3 %
};

TEST_CASE("families: kit accuracy per family") {
  FamilyRun run;  // seed 2027, 30 scenes per family, 300 iterations: the documented table
  run.scenes = 30;
  const auto rows = check_floors(kFloors, [&](const char* name) { return evaluate_family(tf::family(name), ksm_binding(), run); });
  REQUIRE(rows.size() == tf::families().size());
}
