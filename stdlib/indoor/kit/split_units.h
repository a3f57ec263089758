// Units a wall runs through: candidates for a split after the run (after_run.h). The chain's
// SPLIT cuts only along the lines its detector proposes for the unit (Hough segments of its
// interior), and cuts without a door; a unit over several rooms whose dividing walls are
// dashed, or whose two parts need a door to stay joined, can stay whole however much the walls
// inside it cost (measured: lab_ipa, seed 4, one 22 x 11 m hall over four spaces, 30,000 nats
// below the chain of seed 6).
//
// A cut is a line across the unit, parallel to two of its walls and at least kSplitMinPart
// from them, along which the observed grid is wall for at least kSplitWallShare of its length
// and reads as a partition (thin wall for kSplitThinShare of it, where furniture is a thick
// block; no opening wider than the widest door the domain declares, none at all without
// doors). Of the neighbouring lines within 3 cells it is the one where the parts' wall bands
// would lie on the most occupied cells. Each cut is tried as it is and, when its longest
// opening is as wide as a door, with a door there.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/map_evidence.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

inline constexpr double kSplitWallShare = 0.5;  // share of the cut that is wall
inline constexpr double kSplitMinPart = 12.0;   // each part at least this wide, cells (0.6 m at 5 cm)
inline constexpr double kSplitEndMargin = 4.0;  // cells next to the unit's own walls not read
inline constexpr int kSplitReach = 1;           // occupied cells this close across the cut count
inline constexpr int kSplitThinWall = 4;        // a thin wall: open cells within this on both sides, cells
inline constexpr double kSplitThinShare = 0.15; // share of the cut that is thin wall

struct SplitCandidate {
  UnitId unit = 0;
  OrientedRect first, second;  // the two parts
  double share = 0.0;          // share of the cut that is wall
  std::optional<std::pair<Point2, Point2>> door;  // the opening on the cut, when door-wide
};

// The cuts of unit `u` in `observed` (by position: across its w-axis, then its h-axis). Door
// widths in cells. A function of the unit's rectangle and the grid alone.
std::vector<SplitCandidate> split_candidates(const Unit& u, const ClassGrid& observed, double min_door,
                                             double max_door);
// Most walled first (a stable sort: ties keep their order).
void sort_split_candidates(std::vector<SplitCandidate>& cs);
// The cuts of the units of `w`, most walled first (ties by unit id, then position).
std::vector<SplitCandidate> split_candidates(const World& w, const ClassGrid& observed, double min_door,
                                             double max_door);

// The move that replaces c.unit by its two parts (the next two ids, its table), each of its
// doors moved to the part whose wall is nearer (nullopt when a door is farther than
// kMergeDoorSnap from both), plus a door between the parts when `with_door` and c.door.
std::optional<Move> split_move(const World& w, const MapEvidence& ev, const SplitCandidate& c, bool with_door);

}  // namespace ksmc::stdlib::indoor::kit
