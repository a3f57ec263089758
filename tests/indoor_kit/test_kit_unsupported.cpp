// Door-less units the map does not support are removed after the run (stdlib/indoor/kit/
// unsupported_units.h): a strip planted inside a room goes, the result is a local optimum of
// the chain's own target (no further removal, merge or split raises it), units with doors stay, and the step
// is deterministic.
#include <catch2/catch.hpp>

#include <algorithm>

#include "stdlib/indoor/kit/after_run.h"
#include "stdlib/indoor/kit/merged_units.h"
#include "stdlib/indoor/kit/split_units.h"
#include "stdlib/indoor/kit/unsupported_units.h"
#include "tests/indoor/synthetic_map.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor_kit;
namespace mcmc = ksmc::runtime::mcmc;
using ksmc::tests::indoor::draw_plan;
using ksmc::tests::indoor::Room;

namespace {

std::filesystem::path three_rooms() {
  static const std::filesystem::path p = [] {
    const std::vector<Room> rooms{{10, 10, 90, 70}, {90, 10, 170, 70}, {10, 70, 170, 100}};
    const ClassGrid g = draw_plan(110, 180, rooms, 2, {{50, 70}, {130, 70}}, 16);
    return write_pgm(g, temp_dir("unsupported") / "plan.pgm");
  }();
  return p;
}

}  // namespace

TEST_CASE("indoor kit: door-less units the map does not support are removed after the run", "[indoor_kit]") {
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, three_rooms(), 3, {{"resolution", "0.05"}}));
  const auto run = run_chain(setup, 6000, 3);
  auto model = setup.model_factory(0);
  auto& m = static_cast<kit::IndoorModel&>(*model);

  // The chain's best state plus a 6 x 40 cell strip inside the first room (centre 50, 40):
  // nothing proposes such a strip, so REMOVE could never take it away.
  mcmc::Snapshot planted = run.best().best_state;
  const UnitId strip = 9000;
  planted["units"].push_back({{"id", strip}, {"cx", 50.0}, {"cy", 40.0}, {"w", 6.0}, {"h", 40.0}, {"theta", 0.0}, {"lut", 0}});
  m.restore(planted);
  const double with_strip = m.log_posterior();
  REQUIRE(m.scored().world().find_unit(strip) != nullptr);
  const auto doorless = kit::doorless_units(m.scored().world());
  CHECK(std::find(doorless.begin(), doorless.end(), strip) != doorless.end());

  const kit::AfterRunResult r = kit::improve_after_run(m);
  CHECK(r.log_posterior_before == with_strip);
  CHECK(std::find(r.removed.begin(), r.removed.end(), strip) != r.removed.end());
  CHECK(m.scored().world().find_unit(strip) == nullptr);
  CHECK(r.log_posterior_after > r.log_posterior_before);
  CHECK(m.log_posterior() == r.log_posterior_after);

  // A local optimum: removing any door-less unit that is left, or any merge left, does not
  // raise the log posterior (improve() declines and leaves the state as it was).
  const mcmc::Snapshot kept = m.snapshot();
  const World& w = m.scored().world();
  for (const UnitId id : kit::doorless_units(w)) CHECK_FALSE(m.improve(kit::removal(w, id)));
  for (const kit::MergeCandidate& c : kit::merge_candidates(w, m.input().grid))
    CHECK_FALSE(m.improve(kit::merge_move(w, *m.input().evidence, c)));
  for (const kit::SplitCandidate& c : kit::split_candidates(w, m.input().grid, 12.0, 40.0))
    for (const bool with_door : {true, false})
      if (const auto move = kit::split_move(w, *m.input().evidence, c, with_door)) CHECK_FALSE(m.improve(*move));
  CHECK(m.snapshot() == kept);
  CHECK(m.log_posterior() == r.log_posterior_after);

  // Deterministic: the same state gives the same removals and the same world.
  auto again = setup.model_factory(0);
  again->restore(planted);
  auto& m2 = static_cast<kit::IndoorModel&>(*again);
  const kit::AfterRunResult r2 = kit::improve_after_run(m2);
  CHECK(r2.removed == r.removed);
  CHECK(r2.merged == r.merged);
  CHECK(r2.split == r.split);
  CHECK(m2.snapshot() == kept);
}

TEST_CASE("indoor kit: a corridor in two pieces joined by a door is merged after the run; two rooms a wall divides are not", "[indoor_kit]") {
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, three_rooms(), 3, {{"resolution", "0.05"}}));
  auto model = setup.model_factory(0);
  auto& m = static_cast<kit::IndoorModel&>(*model);
  // The plan's two rooms, and its corridor cut at x = 90 into two pieces joined by a door
  // across the whole corridor: a state MERGE cannot undo (a door joins the two).
  auto unit = [](UnitId id, double cx, double cy, double w, double h) {
    return mcmc::Snapshot{{"id", id}, {"cx", cx}, {"cy", cy}, {"w", w}, {"h", h}, {"theta", 0.0}, {"lut", 0}};
  };
  mcmc::Snapshot s = mcmc::Snapshot::object();
  s["units"] = {unit(1, 50, 40, 80, 60), unit(2, 130, 40, 80, 60), unit(3, 50, 85, 80, 30), unit(4, 130, 85, 80, 30)};
  s["doors"] = {{{"id", 1}, {"a", 3}, {"b", 4}, {"ax", 90.0}, {"ay", 72.0}, {"bx", 90.0}, {"by", 98.0}}};
  m.restore(s);

  const auto candidates = kit::merge_candidates(m.scored().world(), m.input().grid);
  auto has = [&](UnitId a, UnitId b) {
    return std::any_of(candidates.begin(), candidates.end(), [&](const kit::MergeCandidate& c) { return c.a == a && c.b == b; });
  };
  CHECK(has(3, 4));
  CHECK_FALSE(has(1, 2));  // the wall between the rooms: no candidate
  CHECK_FALSE(has(1, 3));  // fill of their bounding rectangle below 90 %

  const kit::AfterRunResult r = kit::improve_after_run(m);
  REQUIRE(r.merged.size() == 1);
  CHECK(r.merged[0] == std::make_pair(UnitId{3}, UnitId{4}));
  CHECK(r.log_posterior_after > r.log_posterior_before);
  const World& w = m.scored().world();
  CHECK(w.units().size() == 3);
  CHECK(w.doors().empty());  // the door between the pieces went with the seam
  const auto corridor = std::find_if(w.units().begin(), w.units().end(), [](const Unit& u) { return u.id > 4; });
  REQUIRE(corridor != w.units().end());
  CHECK(corridor->rect.cx == Approx(90.0));
  CHECK(corridor->rect.w == Approx(160.0));
  CHECK(corridor->rect.h == Approx(30.0));
}
