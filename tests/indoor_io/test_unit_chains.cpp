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

TEST_CASE("unit chains: facing sides that meet match, others do not", "[indoor_io]") {
  // 1 and 2 meet end to end 1 cell apart: 2's side (rows 1-21) within 1's (rows 0-22).
  const std::vector<UnitResult> units = {box(1, 0, 0, 50, 22), box(2, 51, 1, 90, 21), box(3, 0, 22, 50, 60),
                                         box(4, 91, 30, 120, 60), box(5, 0, 70, 50, 92)};
  const auto m = matching_sides(units, 2.0);
  REQUIRE(m.size() == 2);
  CHECK(m[0].a == 1);
  CHECK(m[0].b == 2);
  CHECK(m[0].from.x == Approx(50.5));  // midway between x = 50 and x = 51
  CHECK(std::abs(m[0].to.y - m[0].from.y) == Approx(22.0));  // both sides together: rows 0-22
  CHECK(m[0].hi - m[0].lo == Approx(20.0));                  // where they overlap: rows 1-21
  CHECK(m[1].a == 1);  // 1's bottom side and 3's top side
  CHECK(m[1].b == 3);
  // 2 and 4: 4's side starts 9 cells below 2's end; 1 and 5: 48 cells apart.
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

TEST_CASE("unit chains: units continue each other over the whole passage between them", "[indoor_io]") {
  // A passage 18 cells wide (rows 4-21) between walls, drawn as two units whose ends lie in the
  // walls by different amounts (rows 0-22 and 3-25).
  ClassGrid g(30, 100, static_cast<std::uint8_t>(Cell::Occupied));
  for (int r = 4; r <= 21; ++r)
    for (int c = 0; c < 100; ++c) g(r, c) = static_cast<std::uint8_t>(Cell::Free);
  const std::vector<UnitResult> units = {box(1, 0, 0, 50, 22), box(2, 51, 3, 90, 25)};
  CHECK(continued_units(g, units) == std::vector<std::pair<int, int>>{{1, 2}});
  // A door frame on the seam (cols 50-51): an opening of 14 cells of the 18 is closed.
  ClassGrid door = g.clone();
  for (int r = 4; r <= 21; ++r)
    if (r < 6 || r > 19) door(r, 50) = door(r, 51) = static_cast<std::uint8_t>(Cell::Occupied);
  CHECK(continued_units(door, units).empty());
  // The passage runs on past unit 2's end (rows 4-27 free beyond col 50): not continued.
  ClassGrid wide = g.clone();
  for (int r = 22; r <= 27; ++r)
    for (int c = 0; c < 100; ++c) wide(r, c) = static_cast<std::uint8_t>(Cell::Free);
  CHECK(continued_units(wide, {box(1, 0, 0, 50, 28), box(2, 51, 3, 90, 16)}).empty());
}
