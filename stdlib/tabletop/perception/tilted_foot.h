// A tilted box (tilted_box.h) is fitted from the faces the sensor saw. A box leaning steeply
// behind a taller one shows only its upper end: its fit stops where the box in front hides it,
// its lowest corner hangs in the air, and the scene graph calls a box resting on nothing false
// (sim clouds: a pasta box 242 mm long seen as its upper 71 mm, 150 mm above the table).
// When the part below is hidden, the box reaches the table: it grows along one of its axes, on
// that axis's lower side, until its lowest corner is on the table. The part it grows into (the
// box's cross-section over the added length, inset by `inset`) must be hidden, as for an
// upright box's foot (hidden_bottom.h): at least `min_rays` rays end before it and they are at
// least `hidden_share` of the rays that meet it, the rays to the box's own points left out. It
// must not cut into another box deeper than `clear` (a box propped on another stays propped;
// the box itself may cut the box it leans on, which lean_seat.h, run later, mends).
// Of the axes that pass, the least growth is taken; an axis less steep than `min_slope` is not
// tried (a few mm of height would take a long growth), nor a growth over `max_growth`.
#pragma once

#include <cstddef>
#include <vector>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct TiltedFootOptions {
  bool enabled = true;
  double gap = 0.01;          // m; a lowest corner higher than this above the table is grown
  double max_growth = 0.25;   // m along the axis
  double min_slope = 0.3;     // the axis's vertical component, at least
  double inset = 0.005;       // m
  double margin = 0.01;       // m, a ray ending this close to the part ends in it
  std::size_t min_rays = 20;
  double hidden_share = 0.9;
  double clear = 0.003;       // m, the part grown into cuts no other box deeper than this
};

// Grows the tilted boxes of `boxes` (table frame) whose lowest corner is above the table where
// the rays say the part below is hidden. Returns how many grew.
int grow_tilted_feet(std::vector<UprightBox>& boxes, const RayIndex& rays, const TiltedFootOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
