// The indoor model under the runtime/mcmc engine: exact reject, snapshot round trip,
// determinism, and a synthetic plan explained with K > 0.9 and typed units.
#include <catch2/catch.hpp>

#include <iostream>

#include "stdlib/indoor/kit/indoor_model.h"
#include "tests/indoor/synthetic_map.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor_kit;
namespace mcmc = ksmc::runtime::mcmc;
using ksmc::tests::indoor::draw_plan;
using ksmc::tests::indoor::Room;

namespace {

std::filesystem::path plan_file() {
  static const std::filesystem::path p = [] {
    const std::vector<Room> rooms{{10, 10, 90, 70}, {90, 10, 170, 70}, {170, 10, 250, 70}, {10, 70, 250, 100}, {60, 100, 200, 160}};
    const ClassGrid g = draw_plan(175, 265, rooms, 2, {{50, 70}, {130, 70}, {210, 70}, {130, 100}}, 16);
    return write_pgm(g, temp_dir("model") / "plan.pgm");
  }();
  return p;
}

}  // namespace

TEST_CASE("indoor model: a rejected proposal restores the state exactly; one fixed target", "[indoor_kit]") {
  // The shipped binding (tables independent of the types: delayed acceptance) and one whose
  // rooms and halls use another table (units switch tables inside proposals).
  const bool lenient = GENERATE(false, true);
  CAPTURE(lenient);
  auto binding = indoor_binding();
  if (lenient) binding.likelihood.lenient_lut = {{0.6, 0.3, 0.1}, {0.2, 0.6, 0.2}, {0.1, 0.3, 0.6}};
  const auto sp = ksmc::stdlib::indoor::kit::domain_spec(binding);
  const auto setup = sp.load(input_for(sp, plan_file(), 5, {{"source-refresh", "13"}, {"resolution", "0.04"}}));
  auto model = setup.model_factory(0);
  auto& m = static_cast<kit::IndoorModel&>(*model);
  mcmc::Rng rng(11);
  int proposed = 0, relabels = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto& k = setup.kernels[i < 40 ? 0 : static_cast<std::size_t>(i) % setup.kernels.size()];  // ADD first
    const double ll = m.log_likelihood(), lp = m.log_prior();
    const auto p = k->propose(m, rng);
    if (p.was_declined()) {
      CHECK(m.log_likelihood() == ll);
      CHECK(m.log_prior() == lp);
      continue;
    }
    ++proposed;
    if (i % 3 == 0) {
      m.reject();
      CHECK(m.log_likelihood() == ll);
      CHECK(m.log_prior() == lp);
    } else {
      m.accept();
    }
    for (const Unit& u : m.scored().world().units()) relabels += u.lut_class;
    if (i % 50 == 0) {
      // The knowledge term and the tables are those of the world itself, whatever the path.
      const auto fresh = m.semantics()->evaluate(m.scored().world());
      CHECK(fresh.log_knowledge() == Approx(m.log_knowledge()).epsilon(1e-12));
      const auto types = fresh.type;
      for (std::size_t u = 0; u < types.size(); ++u)
        CHECK(m.scored().world().units()[u].lut_class == (lenient && (types[u] == 0 || types[u] == 2) ? 1 : 0));
    }
  }
  CHECK(proposed > 100);
  CHECK((relabels > 0) == lenient);  // Room / Hall units use the lenient table when it differs
  CHECK(m.log_likelihood() == Approx(m.scored().recompute_log_likelihood()).epsilon(1e-9));
  // Snapshot round trip: a fresh model restored to this state scores the same.
  auto fresh = setup.model_factory(0);
  fresh->restore(m.snapshot());
  CHECK(fresh->log_likelihood() == Approx(m.log_likelihood()).epsilon(1e-12));
  CHECK(fresh->log_prior() == Approx(m.log_prior()).epsilon(1e-12));
  CHECK(fresh->snapshot() == m.snapshot());
}

TEST_CASE("indoor model: the engine explains a synthetic plan, deterministically", "[indoor_kit]") {
  const auto sp = spec();
  const auto setup = sp.load(input_for(sp, plan_file(), 3, {{"resolution", "0.04"}}));
  const auto r1 = run_chain(setup, 6000, 3);
  auto best = setup.model_factory(0);
  best->restore(r1.best().best_state);
  auto& m = static_cast<kit::IndoorModel&>(*best);
  CHECK(m.log_posterior() == Approx(r1.best().best_log_posterior).epsilon(1e-9));
  const double k = m.scored().cell_prediction_rate();
  const auto sem = m.final_semantics();
  REQUIRE(sem);
  int rooms = 0, corridors = 0;
  for (int t : sem->type) {
    rooms += t == 0;  // type group order of indoor.ksm: Room, Corr, Hall, Other
    corridors += t == 1;
  }
  std::cout << "indoor kit synthetic plan: K " << k << ", units " << sem->ids.size() << ", rooms " << rooms
            << ", corridors " << corridors << ", doors " << m.scored().world().doors().size() << "\n";
  CHECK(k > 0.9);
  CHECK(rooms >= 3);
  CHECK(corridors >= 1);
  const auto r2 = run_chain(setup, 6000, 3);
  CHECK(r2.best().best_state == r1.best().best_state);
  CHECK(r2.best().final_log_posterior == r1.best().final_log_posterior);
}
