// The synthetic plan family (tools/indoor_sim/plan_family.h) and its scorer
// (bench/indoor_plans/score.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "bench/indoor_plans/score.h"
#include "stdlib/indoor/io/world_json.h"
#include "stdlib/indoor/io/world_json_read.h"
#include "tools/indoor_sim/plan_family.h"

namespace sim = ksmc::tools::indoor_sim;
namespace io = ksmc::stdlib::indoor::io;
using ksmc::bench::indoor_plans::score;

TEST_CASE("make_plan is deterministic in its seed", "[indoor_plans]") {
  const auto a = sim::make_plan(7), b = sim::make_plan(7);
  CHECK(sim::encode_pgm(a.image, a.resolution) == sim::encode_pgm(b.image, b.resolution));
  CHECK(io::world_json_text(a.truth) == io::world_json_text(b.truth));
}

TEST_CASE("different seeds give different plans and every layout occurs", "[indoor_plans]") {
  std::set<std::string> pgms;
  std::set<sim::PlanLayout> layouts;
  for (std::uint64_t s = 1; s <= 12; ++s) {
    const auto p = sim::make_plan(s);
    pgms.insert(sim::encode_pgm(p.image, p.resolution));
    layouts.insert(sim::plan_layout(s));
  }
  CHECK(pgms.size() == 12);
  CHECK(layouts.size() == 3);
}

TEST_CASE("truth units lie on free space, doors on free cells between adjacent units", "[indoor_plans]") {
  for (std::uint64_t s = 1; s <= 20; ++s) {
    INFO("seed " << s);
    const auto p = sim::make_plan(s);
    const auto& w = p.truth;
    REQUIRE(w.units.size() >= 2);
    for (const auto& u : w.units) {
      // Inside the walls (at most 0.3 m thick): mostly free, except furniture and noise.
      const int x0 = static_cast<int>(u.corners[0].x) + 4, y0 = static_cast<int>(u.corners[0].y) + 4;
      const int x1 = static_cast<int>(u.corners[2].x) - 4, y1 = static_cast<int>(u.corners[2].y) - 4;
      REQUIRE(x1 > x0);
      REQUIRE(y1 > y0);
      int free = 0;
      for (int r = y0; r <= y1; ++r) {
        for (int c = x0; c <= x1; ++c) free += p.image(r, c) == 254 ? 1 : 0;
      }
      CHECK(free >= 0.8 * (x1 - x0 + 1) * (y1 - y0 + 1));
      CHECK(p.image(static_cast<int>(u.corners[0].y), static_cast<int>(u.corners[0].x)) == 0);  // a wall corner
    }
    const std::set<std::pair<int, int>> adjacent(w.adjacent.begin(), w.adjacent.end());
    for (const auto& d : w.doors) {
      CHECK(adjacent.count({d.unit_a, d.unit_b}) == 1);
      const int c = static_cast<int>((d.segment[0].x + d.segment[1].x) / 2);
      const int r = static_cast<int>((d.segment[0].y + d.segment[1].y) / 2);
      int free = 0;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) free += p.image(r + dr, c + dc) == 254 ? 1 : 0;
      }
      CHECK(free >= 6);
    }
    // The truth round-trips through world.json.
    CHECK(io::world_json_text(io::parse_world_json(io::world_json_text(w), "truth")) == io::world_json_text(w));
  }
}

TEST_CASE("a truth file scored against itself scores 1 everywhere", "[indoor_plans]") {
  const auto truth = io::parse_world_json(io::world_json_text(sim::make_plan(3).truth), "truth");
  auto found = truth;
  for (auto& u : found.units) {
    u.type = u.type == "room" ? "Room" : u.type == "corridor" ? "Corr" : "Hall";
  }
  const auto s = score(truth, found);
  CHECK(s.unit_precision == 1.0);
  CHECK(s.unit_recall == 1.0);
  CHECK(s.type_accuracy == 1.0);
  CHECK(s.door_precision == 1.0);
  CHECK(s.door_recall == 1.0);
  CHECK(s.door_f1 == 1.0);
  CHECK(s.adjacency_f1 == 1.0);
  CHECK(s.door_graph_f1 == 1.0);
  CHECK(s.topology_f1 == 1.0);
  CHECK(s.matched_units == truth.units.size());
  // A door listed twice is a false positive: precision drops, recall stays.
  found.doors.push_back(found.doors.front());
  const auto d = score(truth, found);
  CHECK(d.door_precision < 1.0);
  CHECK(d.door_recall == 1.0);
}

TEST_CASE("removing a unit lowers the score", "[indoor_plans]") {
  const auto truth = sim::make_plan(3).truth;
  auto found = truth;
  const int gone = found.units.front().id;  // the corridor or hall: every room's door leads there
  found.units.erase(found.units.begin());
  const auto uses = [gone](int a, int b) { return a == gone || b == gone; };
  found.doors.erase(std::remove_if(found.doors.begin(), found.doors.end(),
                                   [&](const auto& d) { return uses(d.unit_a, d.unit_b); }),
                    found.doors.end());
  found.adjacent.erase(std::remove_if(found.adjacent.begin(), found.adjacent.end(),
                                      [&](const auto& e) { return uses(e.first, e.second); }),
                       found.adjacent.end());
  const auto s = score(truth, found);
  CHECK(s.unit_precision == 1.0);
  CHECK(s.unit_recall < 1.0);
  CHECK(s.unit_recall == Approx(static_cast<double>(truth.units.size() - 1) / truth.units.size()));
  CHECK(s.door_f1 < 1.0);
  // Edges to the removed unit are not counted (its truth unit is unmatched).
  CHECK(s.topology_f1 == 1.0);
  // A found unit shifted off its truth rectangle no longer matches.
  auto shifted = truth;
  for (auto& c : shifted.units.back().corners) c.x += 2000.0;
  CHECK(score(truth, shifted).unit_recall < 1.0);
}
