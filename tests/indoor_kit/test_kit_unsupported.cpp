// Door-less units the map does not support are removed after the run (stdlib/indoor/kit/
// unsupported_units.h): a strip planted inside a room goes, the result is a local optimum of
// the chain's own target (no further removal raises it), units with doors stay, and the step
// is deterministic.
#include <catch2/catch.hpp>

#include <algorithm>

#include "runtime/mcmc/engine.h"
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

mcmc::Snapshot without_unit(mcmc::Snapshot s, UnitId id) {
  auto& u = s["units"];
  u.erase(std::remove_if(u.begin(), u.end(), [id](const mcmc::Snapshot& x) { return x.at("id").get<UnitId>() == id; }),
          u.end());
  return s;
}

}  // namespace

TEST_CASE("indoor kit: door-less units the map does not support are removed after the run", "[indoor_kit]") {
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, three_rooms(), 3, {{"resolution", "0.05"}}));
  mcmc::Engine e(setup.model_factory, setup.kernels, setup.schedule);
  mcmc::EngineConfig cfg;
  cfg.iterations = 6000;
  cfg.seed = 3;
  cfg.chains = 1;
  const auto run = e.run(cfg);
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

  const auto doors_before = m.scored().world().doors().size();
  const kit::RemovedUnits r = kit::remove_unsupported_units(m);
  CHECK(r.log_posterior_before == with_strip);
  CHECK(std::find(r.removed.begin(), r.removed.end(), strip) != r.removed.end());
  CHECK(m.scored().world().find_unit(strip) == nullptr);
  CHECK(r.log_posterior_after > r.log_posterior_before);
  CHECK(m.log_posterior() == r.log_posterior_after);
  CHECK(m.scored().world().doors().size() == doors_before);  // units with doors are never tried

  // A local optimum: removing any door-less unit that is left lowers the log posterior.
  const mcmc::Snapshot kept = m.snapshot();
  for (const UnitId id : kit::doorless_units(m.scored().world())) {
    m.restore(without_unit(kept, id));
    CHECK(m.log_posterior() <= r.log_posterior_after);
  }
  m.restore(kept);

  // Deterministic: the same state gives the same removals and the same world.
  auto again = setup.model_factory(0);
  again->restore(planted);
  auto& m2 = static_cast<kit::IndoorModel&>(*again);
  const kit::RemovedUnits r2 = kit::remove_unsupported_units(m2);
  CHECK(r2.removed == r.removed);
  CHECK(m2.snapshot() == kept);
}
