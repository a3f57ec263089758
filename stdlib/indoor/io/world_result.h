// The indoor result as plain data, filled by the domain binary after sampling and written by the
// writers in this folder (world.json, labels.png, segmentation.png, overlay.png, trace.png,
// graph.dot/png, world.obj, posterior.png; docs/indoor_outputs.md).
//
// Coordinates are continuous cell coordinates in the image convention of rect.h: x = column
// (right), y = row (down), origin at the top-left pixel; integer coordinates are cell centres
// (OpenCV's drawing convention), so the cell (c, r) spans [c - 0.5, c + 0.5) x [r - 0.5, r + 0.5).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "stdlib/indoor/io/map_cleanup.h"
#include "stdlib/indoor/io/occupancy_map.h"
#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor::io {

struct UnitResult {
  int id = 0;                                 // > 0; 0 means "no unit" in labels.png and doors
  std::string type;                           // a member of WorldResult::types, "" when untyped
  std::map<std::string, double> type_probs;   // marginals of the type query atoms
  std::array<Point2, 4> corners{};            // in order around the rectangle
};

struct DoorResult {
  int id = 0;
  int unit_a = 0;                    // the two units the door connects (0 = outside / none)
  int unit_b = 0;
  std::array<Point2, 2> segment{};   // end points of the door way
};

struct MapInfo {
  std::string source;                // as given by the caller (written verbatim)
  int width = 0;                     // cells (columns)
  int height = 0;                    // cells (rows)
  double resolution = 0.05;          // m per cell
  Pose2 origin;
  ClassCounts counts;                // of the map after `cleanup`
  MapCleanup cleanup;                // what the run did to the loaded classes (map_cleanup.h)
};

struct TraceSample {
  std::int64_t iteration = 0;
  double log_posterior = 0.0;
  double acceptance_rate = 0.0;      // in [0, 1], e.g. over a sliding window
};

// One stored posterior sample (the chain's accepted state at that iteration): its unit rectangles.
struct PosteriorWorld {
  std::int64_t iteration = 0;
  std::vector<std::array<Point2, 4>> units;
};

struct WorldResult {
  MapInfo map;
  std::vector<UnitResult> units;
  std::vector<DoorResult> doors;
  std::vector<std::pair<int, int>> adjacent;   // unit id pairs, written as given
  // At least cell_prediction_rate, iterations, seconds, iterations_per_second, log_posterior.
  // Integral values are written as JSON integers.
  std::map<std::string, double> metrics;
  std::vector<TraceSample> trace;              // for trace.png (none when empty); not part of world.json
  // The unit types (the domain's exactly-one-of group over units, in declaration order): they
  // pick the unit colours and letters (type_style.h). Written as "types" when not empty.
  std::vector<std::string> types;
  // The marginal of every ground query atom, {"Room": {"u3": 0.91}, "SaLe": {"u3,u7": 0.8}}
  // (units named u<id>; runtime::domain::Semantics::queries_json). Written as "queries", in
  // its own order, when it is an object.
  nlohmann::ordered_json queries;
  // Stored posterior samples, oldest first, for posterior.png; empty (no samples stored, i.e.
  // no --samples) = no posterior.png.
  std::vector<PosteriorWorld> posterior;
  // Width of the wall band the model predicts inside each unit edge (cells), for world.obj.
  double wall_thickness = 1.0;
  // A route (--path) as a polyline in cell coordinates, drawn on overlay.png; empty = none.
  std::vector<Point2> route;
};

// The centre of a unit: the mean of its corners.
inline Point2 unit_centre(const UnitResult& u) {
  return {(u.corners[0].x + u.corners[1].x + u.corners[2].x + u.corners[3].x) / 4.0,
          (u.corners[0].y + u.corners[1].y + u.corners[2].y + u.corners[3].y) / 4.0};
}

// Fills map info (size, resolution, origin, counts) from a loaded map; `source` is written
// verbatim, so pass a relative path or file name for reproducible output.
MapInfo map_info_of(const OccupancyMap& map, const std::string& source);

}  // namespace ksmc::stdlib::indoor::io
