// A unit a wall runs through is split after the run (stdlib/indoor/kit/split_units.h): a hall
// planted over two rooms is cut on the wall between them, with a door in the wall's opening,
// and each of its doors goes to the part whose wall it lies on; a unit with no wall inside is
// no candidate.
#include <catch2/catch.hpp>

#include <algorithm>

#include "stdlib/indoor/kit/after_run.h"
#include "stdlib/indoor/kit/split_units.h"
#include "stdlib/indoor/kit/wall_lines.h"
#include "tests/indoor/synthetic_map.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor_kit;
namespace mcmc = ksmc::runtime::mcmc;
using ksmc::tests::indoor::draw_plan;
using ksmc::tests::indoor::Room;

TEST_CASE("indoor kit: a hall over two rooms is split on the wall between them after the run", "[indoor_kit]") {
  // Two rooms side by side above a corridor; each room has a door to the corridor, and the
  // wall between the rooms (x = 90) an opening 16 cells (0.8 m) wide at y = 40.
  const std::vector<Room> rooms{{10, 10, 90, 70}, {90, 10, 170, 70}, {10, 70, 170, 100}};
  const ClassGrid g = draw_plan(110, 180, rooms, 2, {{50, 70}, {130, 70}, {90, 40}}, 16);
  const auto map = write_pgm(g, temp_dir("split") / "plan.pgm");
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, map, 3, {{"resolution", "0.05"}}));
  auto model = setup.model_factory(0);
  auto& m = static_cast<kit::IndoorModel&>(*model);

  // One hall over both rooms, the corridor, and the two room doors (both on the hall).
  auto unit = [](UnitId id, double cx, double cy, double w, double h) {
    return mcmc::Snapshot{{"id", id}, {"cx", cx}, {"cy", cy}, {"w", w}, {"h", h}, {"theta", 0.0}, {"lut", 0}};
  };
  mcmc::Snapshot s = mcmc::Snapshot::object();
  s["units"] = {unit(1, 90, 40, 160, 60), unit(2, 90, 85, 160, 30)};
  s["doors"] = {{{"id", 1}, {"a", 1}, {"b", 2}, {"ax", 42.0}, {"ay", 70.0}, {"bx", 58.0}, {"by", 70.0}},
                {{"id", 2}, {"a", 1}, {"b", 2}, {"ax", 122.0}, {"ay", 70.0}, {"bx", 138.0}, {"by", 70.0}}};
  m.restore(s);

  const auto candidates = kit::split_candidates(m.scored().world(), m.input().grid, 12.0, 40.0);
  REQUIRE_FALSE(candidates.empty());
  CHECK(std::none_of(candidates.begin(), candidates.end(), [](const kit::SplitCandidate& c) { return c.unit == 2; }));
  const kit::SplitCandidate& best = candidates.front();
  CHECK(best.unit == 1);
  CHECK(best.first.cx + 0.5 * best.first.w == Approx(90.0).margin(1.0));  // on the wall
  REQUIRE(best.door.has_value());
  CHECK(std::abs(best.door->first.y - best.door->second.y) == Approx(16.0).margin(3.0));

  const kit::AfterRunResult r = kit::improve_after_run(m);
  REQUIRE(r.split.size() == 1);
  CHECK(r.split[0] == 1);
  CHECK(r.log_posterior_after > r.log_posterior_before);
  const World& w = m.scored().world();
  REQUIRE(w.units().size() == 3);
  std::vector<UnitId> parts;
  for (const Unit& u : w.units())
    if (u.id > 2) {
      parts.push_back(u.id);
      CHECK(u.rect.w == Approx(80.0).margin(1.0));
      CHECK(u.rect.h == Approx(60.0));
    }
  REQUIRE(parts.size() == 2);
  // Each room keeps its door to the corridor; a third door joins the two rooms.
  REQUIRE(w.doors().size() == 3);
  for (const UnitId p : parts) {
    CHECK(std::count_if(w.doors().begin(), w.doors().end(), [&](const Door& d) {
            return (d.unit_a == p && d.unit_b == 2) || (d.unit_a == 2 && d.unit_b == p);
          }) == 1);
  }
  CHECK(std::any_of(w.doors().begin(), w.doors().end(), [&](const Door& d) {
    return std::min(d.unit_a, d.unit_b) == parts[0] && std::max(d.unit_a, d.unit_b) == parts[1];
  }));
  // No split is left that raises the log posterior.
  const mcmc::Snapshot kept = m.snapshot();
  for (const kit::SplitCandidate& c : kit::split_candidates(w, m.input().grid, 12.0, 40.0))
    for (const bool with_door : {true, false})
      if (const auto move = kit::split_move(w, *m.input().evidence, c, with_door)) CHECK_FALSE(m.improve(*move));
  CHECK(m.snapshot() == kept);
}

TEST_CASE("indoor kit: a room is not split beside a block of furniture, nor where the wall is open wider than a door", "[indoor_kit]") {
  // One room 160 x 90 with a cupboard 12 cells wide and 56 long across 2/3 of its height: a cut
  // through or along it is wall for more than half its length, but the block is thick.
  ClassGrid g = draw_plan(110, 180, {{10, 10, 170, 100}}, 2, {}, 16);
  for (int r = 20; r < 76; ++r)
    for (int c = 80; c < 92; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Occupied);
  // A thin partition at x = 130 with an opening 50 cells wide (2.5 m: no door is that wide).
  for (int r = 10; r < 40; ++r) g(r, 130) = g(r, 131) = static_cast<std::uint8_t>(Cell::Occupied);
  for (int r = 90; r < 100; ++r) g(r, 130) = g(r, 131) = static_cast<std::uint8_t>(Cell::Occupied);
  const auto map = write_pgm(g, temp_dir("split_block") / "plan.pgm");
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, map, 3, {{"resolution", "0.05"}}));
  auto model = setup.model_factory(0);
  auto& m = static_cast<kit::IndoorModel&>(*model);
  mcmc::Snapshot s = mcmc::Snapshot::object();
  s["units"] = {{{"id", 1}, {"cx", 90.0}, {"cy", 55.0}, {"w", 160.0}, {"h", 90.0}, {"theta", 0.0}, {"lut", 0}}};
  s["doors"] = mcmc::Snapshot::array();
  m.restore(s);
  CHECK(kit::split_candidates(m.scored().world(), m.input().grid, 12.0, 40.0).empty());
  // The same partition with an opening a door wide is a candidate.
  for (int r = 40; r < 74; ++r) g(r, 130) = g(r, 131) = static_cast<std::uint8_t>(Cell::Occupied);
  const auto map2 = write_pgm(g, temp_dir("split_door") / "plan.pgm");
  const auto setup2 = sp.load(input_for(sp, map2, 3, {{"resolution", "0.05"}}));
  auto model2 = setup2.model_factory(0);
  auto& m2 = static_cast<kit::IndoorModel&>(*model2);
  m2.restore(s);
  const auto found = kit::split_candidates(m2.scored().world(), m2.input().grid, 12.0, 40.0);
  REQUIRE(found.size() == 1);
  CHECK(found[0].first.cx + 0.5 * found[0].first.w == Approx(131.0).margin(1.0));
  REQUIRE(found[0].door.has_value());
  CHECK(std::min(found[0].door->first.y, found[0].door->second.y) == Approx(74.0).margin(1.5));
}

TEST_CASE("indoor kit: bounded wall sampling stops only where the full sampling would reject the line", "[indoor_kit]") {
  const ClassGrid g = draw_plan(110, 180, {{10, 10, 90, 70}, {90, 10, 170, 70}, {10, 70, 170, 100}}, 2,
                                {{50, 70}, {130, 70}, {90, 40}}, 16);
  int stopped = 0, kept = 0;
  for (const double theta : {0.0, 0.3, 1.2})
    for (double at = 5.0; at < 170.0; at += 3.7)
      for (const bool across_x : {true, false}) {
        const Frame f(theta);
        const kit::FrameLine line{&f, across_x, at, -20.0, 120.0};
        const auto full = kit::wall_samples(g, line, 1);
        REQUIRE(full.size() == kit::sample_count(line));
        std::size_t longest = 0, run = 0, missing = 0;
        for (const bool x : full) {
          run = x ? 0 : run + 1;
          longest = std::max(longest, run);
          missing += x ? 0 : 1;
        }
        for (const auto& [max_open, max_missing] :
             {std::pair<std::size_t, std::size_t>{30, full.size() / 2}, {300, full.size()}}) {
          const auto bounded = kit::wall_samples_bounded(g, line, 1, 0, max_open, max_missing);
          CHECK(bounded.has_value() == (longest <= max_open && missing <= max_missing));
          if (bounded) CHECK(*bounded == full);
          (bounded ? kept : stopped) += 1;
        }
      }
  CHECK(stopped > 0);
  CHECK(kept > 0);
}
