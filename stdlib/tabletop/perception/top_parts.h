// The tops above one plateau that are different boxes. Peeling a stack takes every point above
// the next plateau down as one upper box. When two boxes of about one height stand on either
// side of a lower box, and touch it, their tops are both above its plateau: taken as one, they
// made one box spanning all three, resting on the lower one. An upright box's top is one convex
// face that hides what is under it, so two parts of the tops with a lower surface seen between
// them are two boxes. Parts with only unseen space between them (the shadow of a taller box
// cuts one top in two) stay one box.
#pragma once

#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct TopPartOptions {
  double cell = 0.005;          // m, the grid the tops and the lower surface are read on
  int min_lower_cells = 2;      // cells seen lower on the line between two parts that separate them
  std::size_t min_points = 40;  // a smaller part joins the nearest larger one
};

// `top`: the points above `above` (table frame); `rest`: all of the cluster's points, `top`
// among them. Returns `top` split into boxes (one part when nothing separates them), each
// part's points in their input order, parts ordered by their first point.
std::vector<Points> top_parts(const Points& top, const Points& rest, double above, const TopPartOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
