// Scores an indoor result (world.json) against a truth file of the same schema
// (tools/indoor_sim plan_family / sim_floor_plan truth):
//   * units: matched one-to-one greedily by rectangle IoU (>= 0.5, best pairs first);
//     precision = matched / found units, recall = matched / true units;
//   * type accuracy over matched pairs (Room/Corr/Hall = room/corridor/hall, case-insensitive);
//   * door F1: a found door matches a true door when their midpoints are within 0.5 m
//     (one-to-one, nearest pairs first);
//   * adjacency F1 and door-graph F1 over edges whose two units are both matched (found edges
//     mapped to truth ids); topology F1 = their mean.
// An F1 over two empty sets is 1; an accuracy over no pairs is 0.
#pragma once

#include <cstddef>
#include <string>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::bench::indoor_plans {

struct PlanScore {
  double unit_precision = 0.0;
  double unit_recall = 0.0;
  double type_accuracy = 0.0;
  double door_precision = 0.0;  // matched / found doors
  double door_recall = 0.0;     // matched / true doors
  double door_f1 = 0.0;
  double adjacency_f1 = 0.0;
  double door_graph_f1 = 0.0;
  double topology_f1 = 0.0;  // (adjacency_f1 + door_graph_f1) / 2
  std::size_t true_units = 0;
  std::size_t found_units = 0;
  std::size_t matched_units = 0;
};

inline constexpr double kMinIou = 0.5;
inline constexpr double kDoorTolerance = 0.5;  // m, between door midpoints

// IoU of two convex quadrilaterals (cell coordinates).
double quad_iou(const std::array<stdlib::indoor::Point2, 4>& a, const std::array<stdlib::indoor::Point2, 4>& b);

// "Room" -> "room", "Corr" -> "corridor", "Hall" -> "hall"; others lower-cased.
std::string canonical_type(const std::string& type);

// Metres per cell are the truth's map resolution.
PlanScore score(const stdlib::indoor::io::WorldResult& truth, const stdlib::indoor::io::WorldResult& found);

}  // namespace ksmc::bench::indoor_plans
