// The detectors of stdlib/indoor/detect plugged into the kernels as sources: WBU unit
// candidates, split lines per unit, door candidates per world (cached per world state), the
// dominant orientation as proposal bias; an MH run on a synthetic plan reaches K > 0.9.
#include <catch2/catch.hpp>

#include <iostream>
#include <map>
#include <tuple>

#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/split.h"
#include "stdlib/indoor/detect/wbu.h"
#include "stdlib/indoor/dev_sampler.h"
#include "tests/indoor/synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor;

namespace {

// Door candidates for the latest world, recomputed when the units change.
class DoorCache {
 public:
  explicit DoorCache(const ClassGrid& g) : grid_(g) {}
  std::span<const CandidateDoor> get(const World& w) {
    std::vector<double> key;
    std::vector<OrientedRect> rects;
    for (const Unit& u : w.units()) {
      key.insert(key.end(), {static_cast<double>(u.id), u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta});
      rects.push_back(u.rect);
    }
    auto it = cache_.find(key);
    if (it == cache_.end())
      it = cache_.emplace(key, to_door_candidates(detect::detect_doors(grid_, rects))).first;
    return it->second;
  }

 private:
  const ClassGrid& grid_;
  std::map<std::vector<double>, std::vector<CandidateDoor>> cache_;
};

}  // namespace

TEST_CASE("detectors plug into the kernels and explain a synthetic plan", "[indoor][driver]") {
  const std::vector<Room> rooms{{10, 10, 60, 50}, {60, 10, 100, 50}, {100, 10, 150, 50},
                                {10, 50, 150, 66}, {40, 66, 100, 100}};
  const ClassGrid map = draw_plan(110, 160, rooms, 2, {{35, 50}, {80, 50}, {125, 50}, {70, 66}, {60, 30}}, 6);
  const MapEvidence ev(map, 1);
  const auto wbu = detect::detect_wbu_units(map);
  const auto cands = to_unit_candidates(wbu.candidates);
  REQUIRE(!cands.empty());
  const auto dominant = detect::dominant_orientation(map);

  std::map<std::tuple<double, double, double, double, double>, std::vector<CandidateLine>> split_cache;
  DoorCache doors(map);
  KernelSources src;
  src.units = [&](const World&) { return std::span<const CandidateUnit>(cands); };
  src.split_lines = [&](const World&, const Unit& u) {
    const auto key = std::make_tuple(u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta);
    auto it = split_cache.find(key);
    if (it == split_cache.end())
      it = split_cache.emplace(key, to_line_candidates(detect::detect_split_lines(map, u.rect))).first;
    return it->second;
  };
  src.doors = [&](const World& w) { return doors.get(w); };
  KernelParams kp;
  kp.min_size = 6.0;
  kp.orientation.enabled = true;
  kp.orientation.dominant = dominant.angle_deg * kPi / 180.0;
  KernelSet ks(ev, src, kp);

  ScoreParams sp;
  sp.raster.wall_thickness = 1.0;
  ScoredWorld sw(map, sp);
  DevSampler mh(sw, ks, schedule_table_3_2(), 7);
  mh.run(6000);
  std::cout << "detect plug-in: " << cands.size() << " WBU candidates, dominant " << dominant.angle_deg
            << " deg, K(W,M) " << sw.cell_prediction_rate() << ", units " << sw.world().units().size()
            << ", doors " << sw.world().doors().size() << "\n";
  CHECK(sw.cell_prediction_rate() > 0.9);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-9));
}
