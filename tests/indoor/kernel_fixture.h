// A small floor plan with stand-in bottom-up sources for the kernel tests: three rooms and a
// corridor, unit candidates (the rooms, their exact unions and a few misfits), split lines on
// the plan's inner walls, door candidates on shared walls.
#pragma once

#include <algorithm>
#include <vector>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/kernels.h"
#include "tests/indoor/synthetic_map.h"

namespace ksmc::tests::indoor {

using namespace ksmc::stdlib::indoor;

struct KernelFixture {
  // Rooms A | B | C side by side over a corridor D; doors A-B, B-C, A-D, C-D.
  std::vector<Room> rooms{{10, 10, 50, 40}, {50, 10, 80, 40}, {80, 10, 110, 40}, {10, 40, 110, 52}};
  std::vector<cv::Point> door_points{{50, 25}, {80, 30}, {30, 40}, {95, 40}};
  ClassGrid map = draw_plan(64, 120, rooms, 2, door_points, 4);
  MapEvidence evidence{map, 1};
  std::vector<CandidateUnit> unit_cands;
  std::vector<CandidateLine> lines;
  std::vector<CandidateDoor> door_cands;

  KernelFixture() {
    auto add = [&](const OrientedRect& r) {
      const auto w = evidence.wall_weights(r);
      unit_cands.push_back({r, std::max(*std::min_element(w.begin(), w.end()), 0.02)});
    };
    for (const Room& r : rooms) add(room_rect(r));
    add(room_rect({10, 10, 80, 40}));   // A + B
    add(room_rect({50, 10, 110, 40}));  // B + C
    add(room_rect({10, 10, 110, 40}));  // A + B + C
    add(room_rect({10, 10, 110, 52}));  // everything
    add(OrientedRect{60, 30, 30, 20, 0.3});  // a misfit, rotated
    // Inner walls as split lines, slightly longer and tilted a little.
    lines = {{{50, 8}, {50.5, 42}, 0.0}, {{80, 8}, {80, 42}, 0.0}, {{8, 40}, {112, 40.4}, 0.0},
             {{30, 12}, {30, 38}, 5.0}};
    door_cands = {{{50, 22}, {50, 28}, 0.9}, {{80, 27}, {80, 33}, 0.8}, {{27, 40}, {33, 40}, 0.7},
                  {{92, 40}, {98, 40}, 0.6}, {{20, 5}, {26, 5}, 0.5}};
  }

  KernelSources sources() const {
    KernelSources s;
    s.units = [this](const World&) { return std::span<const CandidateUnit>(unit_cands); };
    // Lines whose midpoint falls inside the unit.
    s.split_lines = [this](const World&, const Unit& u) {
      std::vector<CandidateLine> out;
      const Frame f(u.rect.theta);
      const Box b = own_box(u.rect);
      for (const auto& l : lines) {
        const Point2 m = f.to_local({0.5 * (l.a.x + l.b.x), 0.5 * (l.a.y + l.b.y)});
        if (m.x > b.x0 && m.x < b.x1 && m.y > b.y0 && m.y < b.y1) out.push_back(l);
      }
      return out;
    };
    s.doors = [this](const World&) { return std::span<const CandidateDoor>(door_cands); };
    return s;
  }

  Unit unit(UnitId id, const Room& r) const { return evidence.make_unit(id, room_rect(r)); }
};

// World holding the given units (ids from 1).
inline World world_of(const std::vector<Unit>& units) {
  World w;
  Move m;
  for (const Unit& u : units) m.units.push_back({u.id, std::nullopt, u});
  w.apply(m);
  return w;
}

}  // namespace ksmc::tests::indoor
