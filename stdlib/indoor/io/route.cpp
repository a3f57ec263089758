#include "stdlib/indoor/io/route.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/map_frame.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

namespace {

double dist(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

Point2 midpoint(const DoorResult& d) { return {(d.segment[0].x + d.segment[1].x) / 2.0, (d.segment[0].y + d.segment[1].y) / 2.0}; }

std::string ids_text(const std::vector<int>& ids) {
  std::string s;
  for (const int id : ids) s += (s.empty() ? "" : ", ") + std::to_string(id);
  return s;
}

}  // namespace

std::vector<int> units_containing(const WorldResult& w, Point2 p) {
  std::vector<int> out;
  for (const auto& u : w.units)
    if (finite_quad(u.corners) && depth_inside(u.corners, p) >= 0.0) out.push_back(u.id);
  return out;
}

Route find_route(const WorldResult& w, Point2 start, Point2 goal) {
  validate_world(w, false);
  const std::vector<int> from = units_containing(w, start), to = units_containing(w, goal);
  if (from.empty()) throw RouteError("the start is outside every unit of the world");
  if (to.empty()) throw RouteError("the goal is outside every unit of the world");
  // Nodes: units (by index in w.units), doors (after them), start, goal.
  const std::size_t nu = w.units.size(), nd = w.doors.size(), s = nu + nd, g = s + 1;
  std::map<int, std::size_t> index;
  for (std::size_t i = 0; i < nu; ++i) index[w.units[i].id] = i;
  std::vector<Point2> pos(g + 1);
  for (std::size_t i = 0; i < nu; ++i) pos[i] = unit_centre(w.units[i]);
  for (std::size_t k = 0; k < nd; ++k) pos[nu + k] = midpoint(w.doors[k]);
  pos[s] = start;
  pos[g] = goal;
  std::vector<std::vector<std::size_t>> adj(g + 1);
  const auto link = [&adj](std::size_t a, std::size_t b) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  };
  for (std::size_t k = 0; k < nd; ++k) {
    const auto& d = w.doors[k];
    if (d.unit_a == 0 || d.unit_b == 0 || d.unit_a == d.unit_b) continue;
    link(index.at(d.unit_a), nu + k);
    link(index.at(d.unit_b), nu + k);
  }
  for (const int id : from) link(s, index.at(id));
  for (const int id : to) link(g, index.at(id));
  // Dijkstra; ties broken by node index, so the route is deterministic.
  std::vector<double> best(g + 1, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> prev(g + 1, g + 1);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  best[s] = 0.0;
  queue.push({0.0, s});
  while (!queue.empty()) {
    const auto [d, n] = queue.top();
    queue.pop();
    if (d > best[n]) continue;
    if (n == g) break;
    for (const std::size_t m : adj[n]) {
      if (m == s) continue;
      const double nd2 = d + dist(pos[n], pos[m]);
      if (nd2 < best[m]) {
        best[m] = nd2;
        prev[m] = n;
        queue.push({nd2, m});
      }
    }
  }
  if (!std::isfinite(best[g]))
    throw RouteError(fmt::format("no route: no chain of doors joins the start's unit{} {} to the goal's unit{} {}",
                                 from.size() > 1 ? "s" : "", ids_text(from), to.size() > 1 ? "s" : "", ids_text(to)));
  std::vector<std::size_t> chain;
  for (std::size_t n = g; n != s; n = prev[n]) chain.push_back(n);
  Route r;
  r.waypoints.push_back(start);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const std::size_t n = *it;
    if (n < nu) {
      r.units.push_back(w.units[n].id);
    } else if (n < s) {
      r.doors.push_back(w.doors[n - nu].id);
      r.waypoints.push_back(pos[n]);
    }
  }
  r.waypoints.push_back(goal);
  for (std::size_t i = 1; i < r.waypoints.size(); ++i) r.length += dist(r.waypoints[i - 1], r.waypoints[i]);
  return r;
}

nlohmann::ordered_json route_json(const WorldResult& w, Point2 start, Point2 goal, const Route* route,
                                  const std::string& error) {
  using nlohmann::ordered_json;
  const MapFrame frame = frame_of(w.map);
  const auto metres = [&frame](Point2 p) {
    const Point2 m = frame.to_metres(p);
    return ordered_json::array({std::round(m.x * 1e4) / 1e4, std::round(m.y * 1e4) / 1e4});
  };
  const auto cells = [](Point2 p) { return ordered_json::array({std::round(p.x * 1e3) / 1e3, std::round(p.y * 1e3) / 1e3}); };
  ordered_json j = ordered_json::object();
  j["start"] = {{"m", metres(start)}, {"cells", cells(start)}};
  j["goal"] = {{"m", metres(goal)}, {"cells", cells(goal)}};
  j["found"] = route != nullptr;
  if (!route) {
    j["error"] = error;
    return j;
  }
  j["units"] = route->units;
  j["doors"] = route->doors;
  ordered_json wm = ordered_json::array(), wc = ordered_json::array();
  for (const auto& p : route->waypoints) {
    wm.push_back(metres(p));
    wc.push_back(cells(p));
  }
  j["waypoints_m"] = std::move(wm);
  j["waypoints_cells"] = std::move(wc);
  j["length_m"] = std::round(route->length * w.map.resolution * 1e4) / 1e4;
  return j;
}

nlohmann::ordered_json plan_route(WorldResult& w, Point2 start, Point2 goal, std::string& error) {
  error.clear();
  try {
    const Route r = find_route(w, start, goal);
    w.route = r.waypoints;
    return route_json(w, start, goal, &r, "");
  } catch (const RouteError& e) {
    error = e.what();
    return route_json(w, start, goal, nullptr, error);
  }
}

void write_path_json(const std::filesystem::path& path, const nlohmann::ordered_json& j) {
  runtime::io::write_file_atomic(path, j.dump(2) + "\n");
}

}  // namespace ksmc::stdlib::indoor::io
