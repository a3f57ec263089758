#include "stdlib/indoor/io/world_json_read.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "runtime/io/json_error.h"

#include "stdlib/indoor/io/image_file.h"
#include "stdlib/indoor/io/map_error.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

using nlohmann::json;

namespace {

struct Reader {
  const std::string& name;

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw WorldJsonError(name + ": error: " + where + ": " + what);
  }

  const json& field(const json& obj, const std::string& where, const char* key) const {
    if (!obj.is_object()) fail(where, "expected an object");
    const auto it = obj.find(key);
    if (it == obj.end()) fail(where, std::string("missing key '") + key + "'");
    return *it;
  }

  double number(const json& j, const std::string& where) const {
    if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();  // written for inf/nan
    if (!j.is_number()) fail(where, "expected a number, got " + j.dump());
    return j.get<double>();
  }

  int integer(const json& j, const std::string& where) const {
    if (!j.is_number_integer()) fail(where, "expected an integer, got " + j.dump());
    const auto v = j.get<std::int64_t>();
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      fail(where, "integer out of range");
    }
    return static_cast<int>(v);
  }

  std::string string(const json& j, const std::string& where) const {
    if (!j.is_string()) fail(where, "expected a string, got " + j.dump());
    return j.get<std::string>();
  }

  const json& array(const json& j, const std::string& where, std::size_t size = 0) const {
    if (!j.is_array()) fail(where, "expected an array");
    if (size > 0 && j.size() != size) {
      fail(where, "expected " + std::to_string(size) + " elements, got " + std::to_string(j.size()));
    }
    return j;
  }

  Point2 point(const json& j, const std::string& where) const {
    array(j, where, 2);
    return {number(j[0], where + "[0]"), number(j[1], where + "[1]")};
  }
};

}  // namespace

WorldResult parse_world_json(const std::string& text, const std::string& name) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    const std::size_t upto = std::min<std::size_t>(e.byte, text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(upto), '\n');
    throw WorldJsonError(name + ":" + std::to_string(line) + ": error: JSON syntax: " + e.what());
  } catch (const json::exception& e) {  // out_of_range: a number such as 1e999
    throw WorldJsonError(ksmc::runtime::io::json_error_message(name, text, e));
  }
  const Reader r{name};
  WorldResult w;
  const json& map = r.field(root, "(top level)", "map");
  w.map.source = r.string(r.field(map, "map", "source"), "map.source");
  w.map.width = r.integer(r.field(map, "map", "width"), "map.width");
  w.map.height = r.integer(r.field(map, "map", "height"), "map.height");
  w.map.resolution = r.number(r.field(map, "map", "resolution"), "map.resolution");
  const json& origin = r.array(r.field(map, "map", "origin"), "map.origin", 3);
  w.map.origin = {r.number(origin[0], "map.origin[0]"), r.number(origin[1], "map.origin[1]"),
                  r.number(origin[2], "map.origin[2]")};
  if (map.contains("cells")) {
    const json& cells = map["cells"];
    const auto count = [&](const char* k) {
      const int v = r.integer(r.field(cells, "map.cells", k), std::string("map.cells.") + k);
      if (v < 0) r.fail(std::string("map.cells.") + k, "must not be negative");
      return static_cast<std::size_t>(v);
    };
    w.map.counts = {count("free"), count("unknown"), count("occupied")};
  }
  if (map.contains("cleanup")) {  // absent in world.json files written before it was recorded: none
    const json& cleanup = map["cleanup"];
    w.map.cleanup.speck_cells = r.integer(r.field(cleanup, "map.cleanup", "speck_cells"), "map.cleanup.speck_cells");
    w.map.cleanup.solid_depth_cells =
        r.number(r.field(cleanup, "map.cleanup", "solid_depth_cells"), "map.cleanup.solid_depth_cells");
    if (w.map.cleanup.speck_cells < 0) r.fail("map.cleanup.speck_cells", "must not be negative");
    if (!(w.map.cleanup.solid_depth_cells >= 0.0)) r.fail("map.cleanup.solid_depth_cells", "must not be negative");
  }
  const json& units = r.array(r.field(root, "(top level)", "units"), "units");
  for (std::size_t i = 0; i < units.size(); ++i) {
    const std::string at = "units[" + std::to_string(i) + "]";
    UnitResult u;
    u.id = r.integer(r.field(units[i], at, "id"), at + ".id");
    u.type = r.string(r.field(units[i], at, "type"), at + ".type");
    const json& probs = r.field(units[i], at, "type_probs");
    if (!probs.is_object()) r.fail(at + ".type_probs", "expected an object");
    for (auto it = probs.begin(); it != probs.end(); ++it) {
      u.type_probs[it.key()] = r.number(it.value(), at + ".type_probs." + it.key());
    }
    const json& corners = r.array(r.field(units[i], at, "corners"), at + ".corners", 4);
    for (std::size_t k = 0; k < 4; ++k) {
      u.corners[k] = r.point(corners[k], at + ".corners[" + std::to_string(k) + "]");
    }
    w.units.push_back(u);
  }
  const json& doors = r.array(r.field(root, "(top level)", "doors"), "doors");
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const std::string at = "doors[" + std::to_string(i) + "]";
    DoorResult d;
    d.id = r.integer(r.field(doors[i], at, "id"), at + ".id");
    const json& us = r.array(r.field(doors[i], at, "units"), at + ".units", 2);
    d.unit_a = r.integer(us[0], at + ".units[0]");
    d.unit_b = r.integer(us[1], at + ".units[1]");
    const json& seg = r.array(r.field(doors[i], at, "segment"), at + ".segment", 2);
    d.segment = {r.point(seg[0], at + ".segment[0]"), r.point(seg[1], at + ".segment[1]")};
    w.doors.push_back(d);
  }
  if (root.contains("adjacent")) {
    const json& adj = r.array(root["adjacent"], "adjacent");
    for (std::size_t i = 0; i < adj.size(); ++i) {
      const std::string at = "adjacent[" + std::to_string(i) + "]";
      r.array(adj[i], at, 2);
      w.adjacent.emplace_back(r.integer(adj[i][0], at + "[0]"), r.integer(adj[i][1], at + "[1]"));
    }
  }
  if (root.contains("types")) {
    const json& t = r.array(root["types"], "types");
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (!t[i].is_string()) r.fail("types[" + std::to_string(i) + "]", "expected a string");
      w.types.push_back(t[i].get<std::string>());
    }
  }
  if (root.contains("queries")) {
    if (!root["queries"].is_object()) r.fail("queries", "expected an object");
    w.queries = nlohmann::ordered_json::parse(root["queries"].dump());
  }
  if (root.contains("metrics")) {
    const json& m = root["metrics"];
    if (!m.is_object()) r.fail("metrics", "expected an object");
    for (auto it = m.begin(); it != m.end(); ++it) {
      w.metrics[it.key()] = r.number(it.value(), "metrics." + it.key());
    }
  }
  try {
    validate_world(w, false);
  } catch (const std::invalid_argument& e) {
    throw WorldJsonError(name + ": error: " + e.what());
  }
  return w;
}

WorldResult read_world_json(const std::filesystem::path& path) {
  std::string text;
  try {
    text = read_file_bytes(path);
  } catch (const MapLoadError& e) {
    throw WorldJsonError(e.what());
  }
  return parse_world_json(text, path.string());
}

}  // namespace ksmc::stdlib::indoor::io
