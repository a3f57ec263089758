// --path: Dijkstra over unit centres and door midpoints, the route drawn through door midpoints,
// clear errors for a point outside every unit and for units no door chain joins; the map frame.
#include <catch2/catch.hpp>

#include "stdlib/indoor/io/map_frame.h"
#include "stdlib/indoor/io/route.h"
#include "tests/indoor_io/axis_unit.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::indoor_io::unit;

namespace {

// Three rooms in a row (1 | 2 | 3), doors 1-2 and 2-3, a long way round through a corridor 5
// (doors 1-5 and 5-3), and a room 4 without doors.
WorldResult rooms() {
  WorldResult w;
  w.map.width = 100;
  w.map.height = 60;
  w.units = {unit(1, 0, 0, 20, 20), unit(2, 20, 0, 40, 20), unit(3, 40, 0, 60, 20), unit(4, 70, 0, 90, 20),
             unit(5, 0, 20, 60, 50)};
  w.doors = {DoorResult{11, 1, 2, {Point2{20, 8}, Point2{20, 12}}}, DoorResult{12, 2, 3, {Point2{40, 8}, Point2{40, 12}}},
             DoorResult{13, 1, 5, {Point2{8, 20}, Point2{12, 20}}}, DoorResult{14, 5, 3, {Point2{48, 20}, Point2{52, 20}}},
             DoorResult{15, 4, 0, {Point2{80, 0}, Point2{84, 0}}}};
  return w;
}

}  // namespace

TEST_CASE("route: the shortest chain of doors, drawn through the door midpoints") {
  const WorldResult w = rooms();
  const Route r = find_route(w, {5, 10}, {55, 10});
  CHECK(r.units == std::vector<int>{1, 2, 3});
  CHECK(r.doors == std::vector<int>{11, 12});
  REQUIRE(r.waypoints.size() == 4);
  CHECK(r.waypoints[1].x == Approx(20));
  CHECK(r.waypoints[1].y == Approx(10));
  CHECK(r.length == Approx(50));
  // Start and goal in one unit: a straight line.
  const Route same = find_route(w, {5, 30}, {55, 40});
  CHECK(same.units == std::vector<int>{5});
  CHECK(same.doors.empty());
  CHECK(same.length == Approx(std::hypot(50, 10)));
}

TEST_CASE("route: clear errors") {
  const WorldResult w = rooms();
  CHECK_THROWS_WITH(find_route(w, {95, 55}, {5, 5}), Catch::Contains("start is outside every unit"));
  CHECK_THROWS_WITH(find_route(w, {5, 5}, {95, 55}), Catch::Contains("goal is outside every unit"));
  // Room 4's only door leads outside (unit 0), which is not passable.
  CHECK_THROWS_WITH(find_route(w, {5, 5}, {80, 10}), Catch::Contains("no chain of doors joins the start's unit 1 to the goal's unit 4"));
  WorldResult copy = w;
  std::string error;
  const auto j = plan_route(copy, {5, 5}, {80, 10}, error);
  CHECK(!error.empty());
  CHECK(j.at("found") == false);
  CHECK(copy.route.empty());
  const auto ok = plan_route(copy, {5, 10}, {55, 10}, error);
  CHECK(error.empty());
  CHECK(ok.at("doors") == nlohmann::json::array({11, 12}));
  CHECK(copy.route.size() == 4);
}

TEST_CASE("map frame: cells <-> metres, map_server convention") {
  MapFrame f{0.05, {-10.0, 2.0, 0.0}, 400};
  // The lower-left pixel (col 0, row 399) has its centre half a cell from the origin.
  const Point2 m = f.to_metres({0, 399});
  CHECK(m.x == Approx(-10.0 + 0.025));
  CHECK(m.y == Approx(2.0 + 0.025));
  const Point2 c = f.to_cells({3.3, 7.7});
  const Point2 back = f.to_metres(c);
  CHECK(back.x == Approx(3.3));
  CHECK(back.y == Approx(7.7));
  MapFrame rotated{0.1, {1.0, 1.0, 0.5}, 50};
  const Point2 rc = rotated.to_cells(rotated.to_metres({12.5, 30.0}));
  CHECK(rc.x == Approx(12.5));
  CHECK(rc.y == Approx(30.0));
}
