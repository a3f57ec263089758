// Synthetic floor plans as indoor evidence (.db text) for the indoor knowledge base
// (tests/mln/indoor_kb.h, domains/indoor.ksm), used by the elimination tests and
// bench_mln:
//  * wing(n): a corridor of n/5 segments in a row, each with two rooms on either side;
//    rooms on the same side are adjacent to their neighbours (across segments too),
//    every room to its corridor segment, segment k to segment k+1; the last unit is a
//    hall when n is not a multiple of 5. Nearly planar, induced width about 4.
//  * grid(rows, cols): every unit adjacent to its 4 neighbours (a harder, fully
//    planar case: induced width about min(rows, cols)).
// Geometry evidence: segments are CoLi and MulDoor, rooms RoLi, every 7th room has no
// geometry evidence (ambiguous), every 11th room looks like a hall.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace ksmc::tests::mln {

struct FloorPlan {
  std::int32_t units = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> adjacent;  // unordered pairs a < b
  std::vector<std::uint8_t> corridor;                           // per unit

  static std::string unit_name(std::int32_t u) { return "U" + std::to_string(u); }

  // Evidence lines; `moved` (a unit id) gets its geometry evidence changed (room-like
  // becomes hall-like or back), for incremental tests.
  std::string db(std::int32_t moved = -1) const {
    std::string out;
    std::int32_t room = 0;
    for (std::int32_t u = 0; u < units; ++u) {
      const std::string n = unit_name(u);
      if (corridor[u]) {
        out += "CoLi(" + n + ")\nMulDoor(" + n + ")\n";
        continue;
      }
      ++room;
      const bool hall_like = (room % 11 == 0) != (u == moved);
      if (room % 7 == 0 && u != moved) continue;
      out += (hall_like ? "HaLi(" : "RoLi(") + n + ")\n";
    }
    for (const auto& [a, b] : adjacent) {
      out += "Adj(" + unit_name(a) + ", " + unit_name(b) + ")\n";
      out += "Adj(" + unit_name(b) + ", " + unit_name(a) + ")\n";
    }
    return out;
  }
};

inline FloorPlan wing_plan(std::int32_t n) {
  FloorPlan p;
  p.units = n;
  p.corridor.assign(static_cast<std::size_t>(n), 0);
  const std::int32_t segments = n / 5;
  // unit ids: segment k -> 5k (corridor), 5k+1, 5k+2 (north rooms), 5k+3, 5k+4 (south)
  for (std::int32_t k = 0; k < segments; ++k) {
    const std::int32_t c = 5 * k;
    p.corridor[c] = 1;
    for (std::int32_t r = 1; r <= 4; ++r) p.adjacent.push_back({c, c + r});
    p.adjacent.push_back({c + 1, c + 2});
    p.adjacent.push_back({c + 3, c + 4});
    if (k + 1 < segments) {
      p.adjacent.push_back({c, c + 5});
      p.adjacent.push_back({c + 2, c + 6});
      p.adjacent.push_back({c + 4, c + 8});
    }
  }
  for (std::int32_t u = 5 * segments; u < n; ++u) p.adjacent.push_back({std::max(0, 5 * (segments - 1)), u});
  return p;
}

inline FloorPlan grid_plan(std::int32_t rows, std::int32_t cols) {
  FloorPlan p;
  p.units = rows * cols;
  p.corridor.assign(static_cast<std::size_t>(p.units), 0);
  for (std::int32_t r = 0; r < rows; ++r) {
    for (std::int32_t c = 0; c < cols; ++c) {
      const std::int32_t u = r * cols + c;
      if (r == rows / 2) p.corridor[u] = 1;
      if (c + 1 < cols) p.adjacent.push_back({u, u + 1});
      if (r + 1 < rows) p.adjacent.push_back({u, u + cols});
    }
  }
  return p;
}

}  // namespace ksmc::tests::mln
