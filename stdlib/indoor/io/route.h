// --path: a route between two points of the map over the world's door graph (seed Fig. 3.42).
//
// The search runs Dijkstra on a graph of unit centres and door midpoints: every door between two
// units joins each unit's centre to the door's midpoint (doors to unit 0, the outside, are not
// passable), the start joins the centres of the units containing it, the goal likewise; edge
// weights are straight-line lengths. The route found is then drawn through the units: start,
// the midpoints of the doors it crosses, goal. Consecutive waypoints lie in one unit, and units
// are convex, so each leg stays inside its unit.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// A point outside every unit, or no chain of doors between the two points' units.
class RouteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Route {
  std::vector<int> units;         // unit ids along the route, start's unit first
  std::vector<int> doors;         // door ids crossed, in order (units.size() - 1 of them)
  std::vector<Point2> waypoints;  // cells: start, door midpoints, goal
  double length = 0.0;            // cells, along the waypoints
};

// Ids of the units whose rectangle contains p (boundary included), in w.units order.
std::vector<int> units_containing(const WorldResult& w, Point2 p);

// Throws RouteError naming the point ("start" / "goal") or the two units.
Route find_route(const WorldResult& w, Point2 start, Point2 goal);

// path.json: start and goal in metres and cells, units, doors, waypoints (metres and cells),
// length in metres; or, for `error` not empty, start, goal and the error.
nlohmann::ordered_json route_json(const WorldResult& w, Point2 start, Point2 goal, const Route* route,
                                  const std::string& error);
// --path end to end: finds the route, sets w.route (drawn on overlay.png) when there is one, and
// returns path.json's content; `error` gets RouteError's text ("" on success).
nlohmann::ordered_json plan_route(WorldResult& w, Point2 start, Point2 goal, std::string& error);

void write_path_json(const std::filesystem::path& path, const nlohmann::ordered_json& j);

}  // namespace ksmc::stdlib::indoor::io
