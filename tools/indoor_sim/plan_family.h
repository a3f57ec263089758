// A family of synthetic floor plans with exact ground truth, one per seed, for benchmarking
// (bench/indoor_plans). Each seed draws the building size, a layout (one straight corridor, an
// L-shaped corridor, or a hall), rows of rooms 2-8 m wide, wall thickness 0.1-0.3 m, doors
// 0.8-1.6 m wide (one per room into the corridor/hall, some rooms a second into a neighbour),
// furniture blobs in some rooms and speckle noise. Plans are axis-aligned (no rotation).
// The map is rendered directly (no ray casting): free inside units, walls occupied, unknown
// outside. Truth follows make_sim_office: units are wall centre-line rectangles in cells with
// types room/corridor/hall, doors are segments along the wall centre line, adjacency lists the
// unit pairs sharing a wall. The two legs of an L meet in an opening the corridor's inner width,
// recorded as a door between them.
#pragma once

#include <cstdint>

#include "tools/indoor_sim/sim_floor_plan.h"

namespace ksmc::tools::indoor_sim {

enum class PlanLayout { kStraight, kL, kHall };

// Deterministic in `seed` (std::mt19937_64 with explicit draws; no std distributions).
SimFloorPlan make_plan(std::uint64_t seed);

// The layout make_plan(seed) draws.
PlanLayout plan_layout(std::uint64_t seed);

}  // namespace ksmc::tools::indoor_sim
