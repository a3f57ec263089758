// DoorCandidateCache gives exactly detect_doors' candidates on all units, in the same order,
// while running the detector only on pairs it has not seen.
#include <catch2/catch.hpp>

#include <random>

#include "stdlib/indoor/kit/door_cache.h"
#include "tests/indoor/synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using ksmc::tests::indoor::draw_plan;
using ksmc::tests::indoor::Room;

namespace {

void require_same(const std::vector<CandidateDoor>& a, const std::vector<CandidateDoor>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].a.x == b[i].a.x);
    CHECK(a[i].a.y == b[i].a.y);
    CHECK(a[i].b.x == b[i].b.x);
    CHECK(a[i].b.y == b[i].b.y);
    CHECK(a[i].weight == b[i].weight);
  }
}

OrientedRect box(double x0, double y0, double x1, double y1) {
  return {0.5 * (x0 + x1), 0.5 * (y0 + y1), x1 - x0, y1 - y0, 0.0};
}

}  // namespace

TEST_CASE("door candidate cache equals detect_doors on all units", "[indoor_kit]") {
  const std::vector<Room> rooms{{10, 10, 90, 70}, {90, 10, 170, 70}, {170, 10, 250, 70}, {10, 70, 250, 100}, {60, 100, 200, 160}};
  const ClassGrid g = draw_plan(175, 265, rooms, 2, {{50, 70}, {130, 70}, {210, 70}, {130, 100}, {90, 40}}, 16);
  std::vector<OrientedRect> units;
  for (const Room& r : rooms) units.push_back(box(r.x0, r.y0, r.x1, r.y1));
  detect::DoorParams dp;
  dp.min_door = 6.0;
  dp.max_door = 40.0;
  kit::DoorCandidateCache cache(dp);
  const auto full = to_door_candidates(detect::detect_doors(g, units, dp));
  REQUIRE(full.size() >= 4);  // the plan has five doorways
  require_same(cache.candidates(g, units), full);
  const auto first_calls = cache.detector_calls();
  CHECK(first_calls < units.size() * (units.size() - 1) / 2);  // far pairs skipped
  require_same(cache.candidates(g, units), full);
  CHECK(cache.detector_calls() == first_calls);  // all from the cache
  // Perturb units at random (and reorder them): still identical to the detector.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> shift(0.0, 1.5);
  for (int round = 0; round < 20; ++round) {
    auto& u = units[rng() % units.size()];
    u.cx += shift(rng);
    u.w = std::max(10.0, u.w + shift(rng));
    if (round % 5 == 4) std::swap(units.front(), units.back());
    require_same(cache.candidates(g, units), to_door_candidates(detect::detect_doors(g, units, dp)));
  }
  CHECK(kit::DoorCandidateCache(dp).candidates(g, {units[0]}).empty());
}
