// The shipped domain on a ring of corridors round a courtyard the sensor never saw into (no
// wall round it, as a SLAM map shows glass; speckle in the corridors): the knowledge
// `@no_hollow` forbids the one rectangle over ring and courtyard that the likelihood alone
// prefers to nothing, and the FSU's inner rectangles give the corridors piece by piece.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "stdlib/indoor/blocks.h"
#include "stdlib/indoor/free_distance.h"
#include "stdlib/indoor/kit/indoor_model.h"
#include "tests/indoor_kit/kit_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor_kit;

namespace {

bool inside(const OrientedRect& r, double x, double y) {
  const double c = std::cos(r.theta), s = std::sin(r.theta), dx = x - r.cx, dy = y - r.cy;
  return std::abs(c * dx + s * dy) <= 0.5 * r.w && std::abs(-s * dx + c * dy) <= 0.5 * r.h;
}

}  // namespace

TEST_CASE("indoor kit: a ring of corridors round an unseen courtyard is covered by units, none over the courtyard", "[indoor_kit]") {
  // 10 x 10 m at 0.05 m per cell: walls round the outside, corridors 2.5 m wide, a 5 m
  // courtyard of unknown with no wall, 2 % of the corridor cells unknown.
  ClassGrid g(240, 240, static_cast<std::uint8_t>(Cell::Unknown));
  g(cv::Rect(20, 20, 201, 201)).setTo(static_cast<std::uint8_t>(Cell::Occupied));
  g(cv::Rect(22, 22, 197, 197)).setTo(static_cast<std::uint8_t>(Cell::Free));
  g(cv::Rect(70, 70, 101, 101)).setTo(static_cast<std::uint8_t>(Cell::Unknown));
  std::mt19937 rng(1);
  for (auto& v : g)
    if (v == static_cast<std::uint8_t>(Cell::Free) && rng() % 100 < 2) v = static_cast<std::uint8_t>(Cell::Unknown);
  const auto map = write_pgm(g, temp_dir("courtyard") / "ring.pgm");
  const cv::Mat1f field = free_distance(g);
  for (const std::uint64_t seed : {1u, 2u}) {
    INFO("seed " << seed);
    const auto sp = spec();
    const auto setup = sp.load(input_for(sp, map, seed, {{"resolution", "0.05"}}));
    const auto run = run_chain(setup, 10000, seed);
    auto model = setup.model_factory(0);
    model->restore(run.best().best_state);
    const World& w = static_cast<kit::IndoorModel&>(*model).scored().world();
    const ksmc::stdlib::indoor::blocks::Scene scene(w, 0.05, &g, &field);
    REQUIRE(w.units().size() >= 2);
    for (const Unit& u : w.units()) {
      CHECK_FALSE(ksmc::stdlib::indoor::blocks::geom::hollow(scene, u, 4.0));
      CHECK_FALSE(inside(u.rect, 120, 120));  // the courtyard's centre
    }
    int free = 0, covered = 0;
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.cols; ++c)
        if (g(r, c) == static_cast<std::uint8_t>(Cell::Free)) {
          ++free;
          for (const Unit& u : w.units())
            if (inside(u.rect, c, r)) {
              ++covered;
              break;
            }
        }
    CHECK(covered > 0.9 * free);
  }
}
