#include "stdlib/indoor/io/world_json.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/map_frame.h"

namespace ksmc::stdlib::indoor::io {

using nlohmann::ordered_json;

MapInfo map_info_of(const OccupancyMap& map, const std::string& source) {
  MapInfo info;
  info.source = source;
  info.width = map.cols();
  info.height = map.rows();
  info.resolution = map.resolution;
  info.origin = map.origin;
  info.counts = map.counts();
  return info;
}

namespace {

// Integral values (within the exact double range) become JSON integers: "iterations": 5000.
ordered_json number(double v) {
  if (std::isfinite(v) && std::fabs(v) < 9.0e15 && v == std::floor(v)) {
    return ordered_json(static_cast<std::int64_t>(v));
  }
  if (!std::isfinite(v)) return ordered_json(nullptr);  // JSON has no inf/nan
  return ordered_json(v);
}

ordered_json point(const Point2& p) { return ordered_json::array({number(p.x), number(p.y)}); }

// Metres, rounded to 0.1 mm (far below any map's resolution) for readable, stable output.
double mm(double v) { return std::round(v * 1e4) / 1e4; }
ordered_json point_m(const MapFrame& f, const Point2& cell) {
  const Point2 m = f.to_metres(cell);
  return ordered_json::array({number(mm(m.x)), number(mm(m.y))});
}

}  // namespace

void validate_world(const WorldResult& w, bool require_metrics) {
  std::set<int> ids;
  for (const auto& u : w.units) {
    if (u.id <= 0) throw std::invalid_argument("world: unit id " + std::to_string(u.id) + " must be > 0");
    if (!ids.insert(u.id).second) {
      throw std::invalid_argument("world: duplicate unit id " + std::to_string(u.id));
    }
    if (u.id > 65535) {
      throw std::invalid_argument("world: unit id " + std::to_string(u.id) +
                                  " does not fit the 16-bit labels image");
    }
  }
  const auto known = [&](int id) { return id == 0 || ids.count(id) == 1; };
  for (const auto& d : w.doors) {
    if (!known(d.unit_a) || !known(d.unit_b)) {
      throw std::invalid_argument("world: door " + std::to_string(d.id) + " names unit " +
                                  std::to_string(known(d.unit_a) ? d.unit_b : d.unit_a) +
                                  " which does not exist");
    }
  }
  for (const auto& [a, b] : w.adjacent) {
    if (ids.count(a) == 0 || ids.count(b) == 0) {
      throw std::invalid_argument("world: adjacency (" + std::to_string(a) + ", " +
                                  std::to_string(b) + ") names a unit which does not exist");
    }
  }
  if (require_metrics) {
    for (const char* m : kRequiredMetrics) {
      if (w.metrics.count(m) == 0) {
        throw std::invalid_argument(std::string("world: required metric '") + m + "' is missing");
      }
    }
  }
}

ordered_json world_to_json(const WorldResult& w) {
  ordered_json map = ordered_json::object();
  map["source"] = w.map.source;
  map["width"] = w.map.width;
  map["height"] = w.map.height;
  map["resolution"] = number(w.map.resolution);
  map["origin"] = ordered_json::array(
      {number(w.map.origin.x), number(w.map.origin.y), number(w.map.origin.yaw)});
  map["cells"] = ordered_json{{"free", w.map.counts.free},
                              {"unknown", w.map.counts.unknown},
                              {"occupied", w.map.counts.occupied}};
  map["cleanup"] = ordered_json{{"speck_cells", w.map.cleanup.speck_cells},
                                {"solid_depth_cells", number(w.map.cleanup.solid_depth_cells)}};

  // Every position in cells (image convention, world_result.h) and in map-frame metres
  // (map_frame.h): *_m keys.
  const MapFrame frame = frame_of(w.map);
  const double res = w.map.resolution;
  ordered_json units = ordered_json::array();
  for (const auto& u : w.units) {
    ordered_json probs = ordered_json::object();
    for (const auto& [k, v] : u.type_probs) probs[k] = number(v);  // std::map: sorted keys
    ordered_json corners = ordered_json::array(), corners_m = ordered_json::array();
    for (const auto& c : u.corners) {
      corners.push_back(point(c));
      corners_m.push_back(point_m(frame, c));
    }
    const auto& q = u.corners;
    const double side_w = std::hypot(q[1].x - q[0].x, q[1].y - q[0].y), side_h = std::hypot(q[2].x - q[1].x, q[2].y - q[1].y);
    units.push_back(ordered_json{{"id", u.id}, {"type", u.type}, {"type_probs", probs},
                                 {"corners", corners}, {"corners_m", corners_m},
                                 {"centre_m", point_m(frame, unit_centre(u))},
                                 {"size_m", ordered_json::array({number(mm(side_w * res)), number(mm(side_h * res))})}});
  }
  ordered_json doors = ordered_json::array();
  for (const auto& d : w.doors) {
    const double width = std::hypot(d.segment[1].x - d.segment[0].x, d.segment[1].y - d.segment[0].y);
    doors.push_back(ordered_json{{"id", d.id},
                                 {"units", ordered_json::array({d.unit_a, d.unit_b})},
                                 {"segment", ordered_json::array({point(d.segment[0]),
                                                                  point(d.segment[1])})},
                                 {"segment_m", ordered_json::array({point_m(frame, d.segment[0]), point_m(frame, d.segment[1])})},
                                 {"width_m", number(mm(width * res))}});
  }
  ordered_json adjacent = ordered_json::array();
  for (const auto& [a, b] : w.adjacent) adjacent.push_back(ordered_json::array({a, b}));
  ordered_json metrics = ordered_json::object();
  for (const auto& [k, v] : w.metrics) metrics[k] = number(v);

  ordered_json out = ordered_json::object();
  out["map"] = map;
  out["units"] = units;
  out["doors"] = doors;
  out["adjacent"] = adjacent;
  if (!w.types.empty()) out["types"] = w.types;
  if (w.queries.is_object()) out["queries"] = w.queries;
  out["metrics"] = metrics;
  return out;
}

namespace {

bool is_leaf(const ordered_json& j) {
  if (j.is_primitive()) return true;
  for (const auto& e : j) {
    if (!e.is_primitive() && !(e.is_array() && std::all_of(e.begin(), e.end(), [](const auto& x) {
          return x.is_primitive();
        }))) {
      return false;
    }
  }
  return true;
}

// Pretty printer that keeps small leaves ([col,row] points, corner lists, type_probs) on one line.
void print(const ordered_json& j, int indent, std::string& out) {
  if (is_leaf(j) || j.empty()) {
    std::string s = j.dump();
    if (j.is_object() || j.is_array()) {
      // dump() gives {"a":1,"b":2}; add a space after separators for readability.
      std::string spaced;
      bool in_string = false;
      for (std::size_t i = 0; i < s.size(); ++i) {
        const char ch = s[i];
        spaced += ch;
        if (ch == '"' && (i == 0 || s[i - 1] != '\\')) in_string = !in_string;
        if (!in_string && (ch == ',' || ch == ':')) spaced += ' ';
      }
      s = spaced;
    }
    out += s;
    return;
  }
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  const bool obj = j.is_object();
  out += obj ? "{\n" : "[\n";
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += pad;
    if (obj) out += ordered_json(it.key()).dump() + ": ";
    print(it.value(), indent + 2, out);
  }
  out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + (obj ? "}" : "]");
}

}  // namespace

std::string world_json_text(const WorldResult& w) {
  std::string out;
  print(world_to_json(w), 0, out);
  out += "\n";
  return out;
}

void write_world_json(const std::filesystem::path& path, const WorldResult& w) {
  validate_world(w, true);
  runtime::io::write_file_atomic(path, world_json_text(w));
}

}  // namespace ksmc::stdlib::indoor::io
