// Initial drop configuration: household boxes in columns (stacks 1-3 high) and a few boxes
// leaning against a column, all a few millimetres above their support, ready to be simulated.
#pragma once

#include <optional>
#include <vector>

#include "tools/tabletop_sim/catalogue.h"
#include "tools/tabletop_sim/physics.h"

namespace ksmc::tools::tabletop_sim {

struct LayoutParams {
  std::array<double, 3> stack_height_odds{0.45, 0.35, 0.20};  // columns of 1, 2, 3 boxes
  double lean_rate = 0.4;       // chance that a single box is dropped leaning on a column
  double clearance = 0.012;     // m between the footprints of neighbouring columns
  int placement_tries = 120;    // random positions tried per column before giving up
  Catalogue catalogue = Catalogue::household;
  // Chance that a column of two or more gets a second box on its bottom box, beside the
  // first upper one (one supporter carrying several boxes).
  double side_by_side_rate = 0.0;
};

struct Layout {
  std::vector<BoxItem> items;    // catalogue draws, same order as `bodies`
  std::vector<SimBody> bodies;   // initial (pre-drop) poses in the table frame
  Eigen::Vector2d region_half;   // half extents of the drop region
};

// Horizontal region used for `n` boxes (grows with n, stays inside the table). `spread` >= 1
// widens it for a table too crowded for the usual region (it still stays inside the table).
Eigen::Vector2d drop_region(int n, const TableSpec& table, double spread = 1.0);

// Draws `n` boxes and places them in drop_region(n, table, spread). Returns nullopt when the
// boxes could not be placed without overlap (the caller redraws).
std::optional<Layout> draw_layout(Rng& rng, int n, const TableSpec& table, const LayoutParams& params,
                                  double spread = 1.0);

}  // namespace ksmc::tools::tabletop_sim
