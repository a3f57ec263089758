// Geometry behind the indoor extractors: the Table 3.6 size / aspect-ratio classifier and the
// connecting walls of two units (adjacency, wall-length difference).
#pragma once

#include <cmath>
#include <optional>

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor::blocks {

enum class GeomClass : unsigned char { RoomLike, CorridorLike, HallLike };

// Table 3.6: hall-like when the longer side exceeds big_size_m; otherwise corridor-like when
// longer / shorter exceeds big_ratio, else room-like. A unit whose longer / shorter exceeds
// big_ratio and whose shorter side is at most corridor_width_m is corridor-like at any length
// (0: the table as printed, where a long corridor reads as hall-like). `resolution` in m per cell.
GeomClass classify_unit(const OrientedRect& r, double resolution, double big_size_m, double big_ratio,
                        double corridor_width_m);

// The connecting walls of two units: the pair of nearly parallel edges (within 10 degrees)
// closest across and overlapping along by more than `dilate_cells`, both within
// 2 * dilate + 1 cells. nullopt when none.
struct WallPair {
  int wall_a = 0, wall_b = 0;
  double overlap = 0.0;                   // cells along the walls
  double length_a = 0.0, length_b = 0.0;  // cells
};
std::optional<WallPair> connecting_walls(const OrientedRect& a, const OrientedRect& b, double dilate_cells);

// A rectangle's side along its edge `edge` and its depth away from that edge (the other side).
// Corners run (-w,-h), (+w,-h), (+w,+h), (-w,+h): edges 0 and 2 are |w| long, 1 and 3 |h|.
inline double edge_length(const OrientedRect& r, int edge) { return edge % 2 == 0 ? std::abs(r.w) : std::abs(r.h); }
inline double depth_from_edge(const OrientedRect& r, int edge) { return edge % 2 == 0 ? std::abs(r.h) : std::abs(r.w); }

// Whether the cut between two units that tile a rectangle runs across a corridor: their
// connecting wall (dilate 2 cells) is at most `max_cut` cells long, and the rectangle they make
// is at least `min_ratio` times as long, across the cut, as the cut. Symmetric; false when the
// two share no wall.
bool cut_across_corridor(const OrientedRect& a, const OrientedRect& b, double max_cut, double min_ratio);

// The dilation of geom.adjacent's default (stdlib/indoor.ksm), used where a block has none.
inline constexpr double kDefaultDilateCells = 2.0;

}  // namespace ksmc::stdlib::indoor::blocks
