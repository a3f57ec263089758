// matching_sides / continued_units: units whose facing sides coincide, and those of them with an
// open seam on the map.
#include <catch2/catch.hpp>

#include <cmath>

#include "stdlib/indoor/io/unit_chains.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;

namespace {

UnitResult box(int id, double x0, double y0, double x1, double y1) {
  UnitResult u;
  u.id = id;
  u.corners = {Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}};
  return u;
}

}  // namespace

TEST_CASE("unit chains: facing sides that coincide match, others do not", "[indoor_io]") {
  // 2 and 1 meet end to end (2's side 20 cells, 1's 22: 20 >= 0.85 * 22), 1 cell apart.
  const std::vector<UnitResult> units = {box(1, 0, 0, 50, 22), box(2, 51, 1, 90, 21), box(3, 0, 22, 50, 60),
                                         box(4, 90, 0, 120, 40), box(5, 0, 70, 50, 92)};
  const auto m = matching_sides(units, 2.0);
  REQUIRE(m.size() == 2);
  CHECK(m[0].a == 1);
  CHECK(m[0].b == 2);
  CHECK(m[0].side == Approx(22.0));
  CHECK(m[0].from.x == Approx(50.5));  // midway between x = 50 and x = 51
  CHECK(std::abs(m[0].to.y - m[0].from.y) == Approx(20.0));
  CHECK(m[1].a == 1);  // 1's bottom side and 3's top side: the same 50 cells
  CHECK(m[1].b == 3);
  // 2 and 4: 4's side is 40 cells, 2's 20 (under 0.85 of it); 1 and 5: 48 cells apart.
  CHECK(matching_sides(units, 0.5).size() == 1);  // 2 is 1 cell from 1: beyond a gap of 0.5
  // 2 turned by 3 degrees about its west side's middle (51, 11), more than kSideAngleDeg: no match.
  UnitResult turned = units[1];
  const double a = 3.0 * 3.14159265358979 / 180.0;
  for (auto& p : turned.corners) {
    const double x = p.x - 51.0, y = p.y - 11.0;
    p = Point2{51.0 + x * std::cos(a) - y * std::sin(a), 11.0 + x * std::sin(a) + y * std::cos(a)};
  }
  CHECK(matching_sides({units[0], turned}, 2.0).empty());
}

TEST_CASE("unit chains: a seam continues when it is free on the map", "[indoor_io]") {
  ClassGrid g(30, 100, static_cast<std::uint8_t>(Cell::Free));
  const std::vector<UnitResult> units = {box(1, 0, 0, 50, 22), box(2, 51, 1, 90, 21)};
  CHECK(continued_units(g, units) == std::vector<std::pair<int, int>>{{1, 2}});
  // A wall on the seam (col 50-51) with an opening of 4 cells of 21: closed.
  for (int r = 0; r < 30; ++r)
    if (r < 9 || r > 12) g(r, 50) = g(r, 51) = static_cast<std::uint8_t>(Cell::Occupied);
  CHECK(continued_units(g, units).empty());
}
