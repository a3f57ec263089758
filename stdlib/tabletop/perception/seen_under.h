// A box standing on the table that the sensor saw under. Euclidean clustering and the box fit
// take a box resting on a smaller one whose top it hides (a book on a lying rice box, a
// tissue box on a lying pasta box) for one box from the table up: no plateau of the lower box
// is visible, and its side faces stand back under the overhang. The cloud's rays tell: where
// the upper box overhangs, the sensor saw the table (or the lower box's faces) below it,
// through the space the single box claims. Each ray (sensor -> point, stopping `margin`
// before the point) that crosses the box's footprint (inset by `inset`) reaches some highest
// height inside it (rays to the box's own side faces, points within `margin` of them, are left
// out: depth noise along a grazing ray carries them into the box); the `min_rays`-th highest of those is the height up to which the sensor
// saw through the box. Above `min_cut`, with at least `min_upper` of box above it, the box is
// cut there: the points above are the upper box, resting at that height, and the points
// below (when there are `min_points`) are fitted as the box it rests on. Points below the cut
// that reach the box's outline on every side (within `margin`) are its own side faces, not a
// narrower box's: a cloud that holds points the sensor could not have seen (several views
// merged, or the table sampled under the boxes) crosses boxes that are solid, and is left alone.
// A box that floats (its cluster starts above BoxFitOptions::float_gap: its foot is hidden) is
// read the same way from its own bottom up: a tissue box lying on a cereal box whose lower
// part a neighbour hides; its lower part then floats too (grow_hidden_bottoms may extend it).
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/box_fit.h"
#include "stdlib/tabletop/perception/side_steps.h"

namespace ksmc::stdlib::tabletop::perception {

struct SeenUnderOptions {
  bool enabled = true;
  double inset = 0.003;         // m, the footprint shrunk by this on every side ...
  double noise_inset = 3.0;     // ... or by this times the table plane's RMS (scene_from_points), if more
  double margin = 0.01;         // m kept before each ray's point (its own surface)
  std::size_t min_rays = 20;
  double min_cut = 0.03;        // m; lower cuts are not told from the table's edge noise
  double min_upper = 0.02;      // m of box above the cut
  std::size_t min_points = 40;  // points under the cut that make a box of their own
  // A box fitted to a merged cluster is as wide as the union of what it holds: a lower box
  // turned under the upper one pokes out at its corners, and the rays past the upper box's edge
  // cross those strips of the fitted box up to its top, so the height they saw up to is its top.
  // Then the rays are read once more under the top face alone (the minimal rectangle of the
  // points within `top_band` of the top, trimmed by `top_trim`; at least `min_top_points`) when
  // that rectangle is narrower than the box by more than `top_excess` on a side yet covers at
  // least `top_cover` of its footprint (a top seen whole, not cut by an occluder). Sim seed 7,
  // singles 0: a cereal box on a tissue box turned 18 degrees under it; seed 21, propped 9: a
  // tissue box on a pasta box. Off: top_band 0.
  double top_band = 0.008;      // m
  std::size_t min_top_points = 20;
  double top_trim = 0.003;
  double top_excess = 0.005;    // m
  double top_cover = 0.8;
};

// The height (table frame, z up) up to which the rays (RayIndex: the cloud and its sensor) saw
// through `box` (an upright box),
// 0 when fewer than options.min_rays rays cross it.
double seen_under_height(const UprightBox& box, const RayIndex& rays, const SeenUnderOptions& options = {});

// The boxes that replace `box` (upright; `points` are its points) when the sensor saw under it:
// the lower part's boxes (fit_column from the table, or from the box's bottom when that is
// above fit.float_gap) when it has options.min_points points, then the upper part's, resting at
// the cut. Empty: `box` stays as it is.
std::vector<UprightBox> cut_seen_under(const UprightBox& box, const Points& points, const RayIndex& rays,
                                       const BoxFitOptions& fit, const SideStepOptions& sides,
                                       const SeenUnderOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
