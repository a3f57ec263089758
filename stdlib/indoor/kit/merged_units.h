// Pairs of units that nearly tile a rectangle: candidates for a merge after the run
// (after_run.h). The chain's MERGE joins two units only when they tile a rectangle exactly
// and no door joins them (SPLIT, its reverse, cuts without a door). So a corridor that SPLIT
// cut and ALLOCATE then joined by a door, or two pieces SHRINK / DILATE moved a cell apart,
// stay two units, whatever one unit would gain.
//
// Only units with no wall between them are candidates (the knowledge's "two adjacent units with
// no wall between them are one space"): the posterior alone would also merge two rooms across a
// one-cell partition with an opening, since a unit edge on a one-cell wall gains nothing in the
// likelihood (measured on office_i: two halls of the benchmark's truth joined, IoU 0.96 -> 0.92).
#pragma once

#include <vector>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/map_evidence.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::kit {

inline constexpr double kMergeAngleDeg = 2.0;  // orientations agree this well (mod 90 deg)
inline constexpr double kMergeFill = 0.9;      // share of the bounding rectangle a or b covers
inline constexpr double kMergeDoorSnap = 2.0;  // a carried door this close to the new walls, cells
inline constexpr double kMergeWallShare = 0.2;  // at most this share of the seam may be wall
inline constexpr int kMergeSeamReach = 2;       // occupied cells this close across the seam count, cells
inline constexpr double kMergeSeamTrim = 0.15;  // share of the seam left out at each end

struct MergeCandidate {
  UnitId a = 0, b = 0;  // a < b
  OrientedRect rect;    // the new rectangle, in a's frame (merge_candidates: which ones)
  double fill = 0.0;    // share of `rect` that a or b covers
};

// The pairs of `w` whose bounding rectangle they fill to at least kMergeFill and whose seam (the
// line between them, where they neither overlap nor nest) is at most kMergeWallShare wall in
// `observed`. Per pair up to four rectangles: along the line they join along, from the first's
// end to the other's; across it, the span of both, their common span, or one unit's span (in
// that order, repeats left out). A rectangle is a candidate when the pair's other doors (not the
// ones joining the two) lie on its walls. Most filled pairs first (ties by ids).
std::vector<MergeCandidate> merge_candidates(const World& w, const ClassGrid& observed);

// The move that replaces c.a and c.b of `w` by one unit (the next id, c.a's table) of rectangle
// c.rect: the doors joining them go, their other doors move to it.
Move merge_move(const World& w, const MapEvidence& ev, const MergeCandidate& c);

}  // namespace ksmc::stdlib::indoor::kit
