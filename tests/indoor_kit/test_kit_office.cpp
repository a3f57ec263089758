// A domain file the kit has never seen: domains/indoor.ksm with a fifth unit type Office
// (tests/indoor_kit/CMakeLists.txt writes it): a new evidence predicate on an existing
// extractor with other parameters, two rules, Office lenient. It must reach the types, the
// type probabilities (summing to 1), the lenient table and the outputs, with no kit change.
#include <catch2/catch.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "indoor_office_factors.h"
#include "indoor_office_model.h"
#include "runtime/mcmc/engine.h"
#include "stdlib/indoor/kit/indoor_model.h"
#include "stdlib/indoor/kit/kit.h"
#include "stdlib/indoor/kit/semantic_layer.h"
#include "tests/indoor/synthetic_map.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::kit;
namespace gen = ksmc_generated::indoor_office;
namespace blk = ksmc::stdlib::indoor::blocks;

TEST_CASE("an added type of the domain file reaches the kit's types, probabilities and lenient table", "[indoor_kit]") {
  const blk::Binding& b = gen::binding();
  const KitPlan plan = make_plan(b);
  REQUIRE(plan.type_predicates.size() == 5);
  CHECK(plan.type_predicates.back() == gen::kPred_Office);
  CHECK(plan.lenient == std::vector<bool>{true, false, true, false, true});
  SemanticLayer sem(b, plan, 0.05, nullptr, 1);
  CHECK(sem.type_names() == std::vector<std::string>{"Room", "Corr", "Hall", "Other", "Office"});
  // A 4 x 3 m room, a 9 x 2 m corridor and a 2.5 x 2 m office (Small: longer side <= 3 m).
  Move m;
  const std::vector<OrientedRect> rects{{40, 30, 80, 60, 0}, {80, 80, 180, 40, 0}, {200, 30, 50, 40, 0}};
  for (UnitId id = 1; id <= 3; ++id) m.units.push_back({id, std::nullopt, Unit{id, rects[id - 1]}});
  World w;
  w.apply(m);
  const SemanticResult r = sem.evaluate(w);
  CHECK(r.type == std::vector<int>{0, 1, 4});  // Room, Corr, Office
  for (const auto& probs : r.type_probs) {
    REQUIRE(probs.size() == 5);
    double total = 0.0;
    for (double p : probs) total += p;
    CHECK(total == Approx(1.0).epsilon(1e-6));
  }
  const auto q = sem.queries_json(r);
  CHECK(q.at("Office").at("u3").get<double>() == Approx(r.type_probs[2][4]));
  CHECK(sem.evidence_db(r).find("\nSmall(u3)\n") != std::string::npos);
}

TEST_CASE("the Office domain runs end to end: world.json reports Office units", "[indoor_kit]") {
  using ksmc::tests::indoor::draw_plan;
  using ksmc::tests::indoor::Room;
  namespace ti = ksmc::tests::indoor_kit;
  // Three 2.4 m x 2.4 m offices and a 4 m x 2.4 m room above a corridor, at 0.04 m per cell.
  const std::vector<Room> rooms{{10, 10, 70, 70}, {70, 10, 130, 70}, {130, 10, 190, 70}, {190, 10, 290, 70}, {10, 70, 290, 100}};
  const ClassGrid g = draw_plan(115, 305, rooms, 2, {{40, 70}, {100, 70}, {160, 70}, {240, 70}}, 16);
  const auto map = ti::write_pgm(g, ti::temp_dir("office") / "plan.pgm");
  const auto spec = domain_spec(gen::binding());
  const auto setup = spec.load(ti::input_for(spec, map, 3, {{"resolution", "0.04"}}));
  ksmc::runtime::mcmc::Engine e(setup.model_factory, setup.kernels, setup.schedule);
  ksmc::runtime::mcmc::EngineConfig cfg;
  cfg.iterations = 6000;
  cfg.seed = 3;
  const auto run = e.run(cfg);
  auto best = setup.model_factory(0);
  best->restore(run.best().best_state);
  const auto out = ti::temp_dir("office_out");
  ksmc::runtime::cli::OutputDir dir(out);
  setup.write_results(run, *best, dir);
  dir.commit();
  const auto world = nlohmann::json::parse(std::ifstream(out / "world.json"));
  CHECK(world.at("types").size() == 5);
  int offices = 0;
  for (const auto& u : world.at("units")) {
    offices += u.at("type") == "Office";
    double total = 0.0;
    for (const auto& [t, p] : u.at("type_probs").items()) total += p.get<double>();
    CHECK(total == Approx(1.0).epsilon(1e-5));
  }
  INFO(world.at("units").dump());
  CHECK(offices >= 2);
  CHECK(world.at("queries").contains("Office"));
}
