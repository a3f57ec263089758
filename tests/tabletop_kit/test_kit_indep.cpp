// The independent scene generator (tools/tabletop_indep) and the kit's accuracy on its
// families (issue 12: "scenes the project has not generated"). The generator cases check that
// its worlds are what it claims (boxes apart or touching by construction, stacks in
// equilibrium, leaning boxes on the table and their wall) and that each family brings what it
// varies. The accuracy case asserts each family's figures: the targets where the kit
// reaches them, otherwise the measured value less 0.03 (docs/tabletop_families.md,
// "Independent generator", lists the gaps).
#include <catch2/catch.hpp>

#include <algorithm>
#include <iostream>
#include <set>

#include "tests/tabletop_kit/family_floors.h"
#include "tests/tabletop_kit/indep_eval.h"

using namespace ksmc::tests::tabletop_kit;

namespace {

ti::IndepScene scene_of(const char* name, std::uint64_t i) {
  const auto& f = ti::family(name);
  return ti::generate(f, ti::scene_seed(f, 11, i));
}

}  // namespace

TEST_CASE("pooled line: the families' exact counts summed") {
  FamilyScore a, b;
  a.score.is_false = {3, 1, 2};  // tp fp fn
  b.score.is_false = {5, 0, 1};
  a.score.is_hidden = {2, 0, 0};
  a.score.positives = 7;
  b.score.positives = 3;
  b.score.positive_undecided = 1;
  const std::string line = pooled_line({a, b});
  // false: tp 8 fp 1 fn 3 -> P 8/9, R 8/11, F1 16/20 = 0.8 (the rows' rounded P and R would not give it)
  CHECK_THAT(line, Catch::StartsWith("pooled over 2 families: false P R F1 0.889 0.727 0.800 (tp 8 fp 1 fn 3) | "
                                     "hidden P R F1 1.000 1.000 1.000 (tp 2 fp 0 fn 0) | "));
  CHECK_THAT(line, Catch::EndsWith("| undecided 10.0 % of 10 positives\n"));
}

TEST_CASE("indep: known names, deterministic scenes, disjoint seeds") {
  REQUIRE(ti::families().size() == 9);
  CHECK_THROWS_WITH(ti::family("nope"), Catch::Contains("unknown family 'nope'") && Catch::Contains("indep_leaning"));
  CHECK(scene_of("indep_mixed", 3).scene_json() == scene_of("indep_mixed", 3).scene_json());
  CHECK(scene_of("indep_mixed", 3).truth_json() == scene_of("indep_mixed", 3).truth_json());
  CHECK(ti::scene_seed(ti::family("indep_base"), 1, 0) != ti::scene_seed(ti::family("indep_camera"), 1, 0));
  CHECK(ti::scene_seed(ti::family("indep_base"), 1, 0) != ti::scene_seed(ti::family("indep_base"), 1, 1));
}

TEST_CASE("indep: worlds are physically what the truth says") {
  long stacked = 0, leaning = 0, flush = 0;
  for (const auto& f : ti::families()) {
    for (std::uint64_t i = 0; i < 8; ++i) {
      const ti::IndepScene s = ti::generate(f, ti::scene_seed(f, 5, i));
      const auto& bodies = s.world.bodies;
      INFO(f.name << " scene " << i);
      for (std::size_t a = 0; a < bodies.size(); ++a) {
        const ti::Body& b = bodies[a];
        if (b.leans_on >= 0) {
          ++leaning;
          CHECK(std::abs(b.box.bottom()) < 1e-9);  // on the table
          CHECK(b.box.tilt() > 0.15);
          const ti::Obb& wall = bodies[static_cast<std::size_t>(b.leans_on)].box;
          CHECK(std::abs(ti::penetration(wall, b.box)) < 1e-3);  // touches
          // Its centre of mass lies on the wall's side of the edge it stands on: it leans.
          const auto corners = b.box.corners();
          const Eigen::Vector3d low = *std::min_element(corners.begin(), corners.end(), [](const auto& p, const auto& q) { return p.z() < q.z(); });
          const Eigen::Vector3d local = wall.rot.transpose() * (b.box.centre - wall.centre);
          const Eigen::Vector3d nearest = wall.centre + wall.rot * local.cwiseMax(-wall.half()).cwiseMin(wall.half());
          const Eigen::Vector2d to_wall = (nearest - b.box.centre).head<2>().normalized();
          CHECK((b.box.centre - low).head<2>().dot(to_wall) > 0.0079);
        } else {
          CHECK(b.box.tilt() < 1e-6);
          REQUIRE(b.rests_on.size() == 1);
          const int s0 = b.rests_on[0];
          if (s0 == ti::kTable) {
            CHECK(std::abs(b.box.bottom()) < 1e-9);
          } else {
            ++stacked;
            const ti::Obb& lower = bodies[static_cast<std::size_t>(s0)].box;
            CHECK(std::abs(b.box.bottom() - lower.top()) < 1e-9);
            CHECK(ti::over_top(lower, b.box.centre.head<2>(), 0.0));  // centre of mass over the supporter
          }
        }
        for (std::size_t c = a + 1; c < bodies.size(); ++c) CHECK(ti::penetration(bodies[a].box, bodies[c].box) < 1e-3);
      }
      for (const auto& [a, c] : s.world.contact) flush += a >= 0 && c >= 0 && bodies[static_cast<std::size_t>(c)].leans_on < 0;
    }
  }
  CHECK(stacked >= 20);
  CHECK(leaning >= 5);
  CHECK(flush >= 5);
}

TEST_CASE("indep: each family brings what it varies") {
  std::set<std::string> labels, kinds;
  bool numeric = false;
  long hidden = 0, few_keypoints = 0;
  for (std::uint64_t i = 0; i < 8; ++i) {
    for (const auto& b : scene_of("indep_catalogue", i).world.bodies) labels.insert(b.label);
    for (const auto& e : scene_of("indep_false_kinds", i).estimates) kinds.insert(ti::to_string(e.kind));
    numeric = numeric || nlohmann::json::parse(scene_of("indep_mixed", i).scene_json())["objects"][0]["id"].is_number();
    const auto h = scene_of("indep_hidden", i);
    for (const auto& e : h.estimates) hidden += e.body >= 0 && h.world.hidden(e.body);
    for (const auto& e : scene_of("indep_keypoints", i).estimates) few_keypoints += e.kp_model.size() <= 20;
  }
  CHECK(labels.count("cube") + labels.count("board") + labels.count("bar") == 3);
  CHECK(kinds.size() >= 6);  // "none" and at least five of the seven false kinds
  CHECK(numeric);
  CHECK(hidden >= 6);
  CHECK(few_keypoints >= 10);
}

// Per family: the least false F1, hidden F1, support-edge F1 and the largest undecided share.
// Measured at seed 2027, 30 scenes, 300 iterations (main at the commit that added them).
const Floor kFloors[] = {
    {"indep_base", 0.71, 0.81, 0.95, 8.3},         // measured 0.74 / 0.84 / 0.97, 5.3 %
    {"indep_pose_noise", 0.67, 0.90, 0.95, 5.0},   // measured 0.70 / 1.00 / 0.97, 0.0 %
    {"indep_camera", 0.72, 0.72, 0.95, 12.7},      // measured 0.75 / 0.75 / 0.97, 3.2 %; with r28 0.77 / 0.75 / 0.97, 9.7 %
    {"indep_keypoints", 0.83, 0.90, 0.95, 11.0},   // measured 0.86 / 0.92 / 0.99, 4.0 %; with r30 0.85 / 0.92 / 0.99, 8.0 %
    {"indep_catalogue", 0.62, 0.40, 0.95, 21.5},   // measured 0.65 / 0.43 / 0.96, 18.5 %
    {"indep_false_kinds", 0.82, 0.59, 0.95, 10.0}, // measured 0.85 / 0.62 / 0.98, 7.0 %
    {"indep_hidden", 0.40, 0.90, 0.95, 12.3},      // measured 0.43 / 0.94 / 0.98, 9.3 %
    {"indep_leaning", 0.82, 0.86, 0.95, 8.6},      // measured 0.85 / 1.00 / 1.00, 5.6 %; with r28 0.85 / 0.89 / 0.99, 5.6 %
    {"indep_mixed", 0.86, 0.77, 0.95, 12.1},       // measured 0.89 / 0.94 / 0.96, 9.1 %; with r28 and the
                                                   // engine's per-term log a 0.91 / 0.88 / 0.96, 6.1 % (one hidden missed);
                                                   // with r32 0.89 / 0.80 / 0.96, 6.1 % (one more hidden missed, 2 of 8)
};

TEST_CASE("indep: kit accuracy per family") {
  FamilyRun run;  // seed 2027, 30 scenes per family, 300 iterations
  run.scenes = 30;
  const auto rows = check_floors(kFloors, [&](const char* name) { return evaluate_indep_family(ti::family(name), ksm_binding(), run); });
  REQUIRE(rows.size() == ti::families().size());
}
