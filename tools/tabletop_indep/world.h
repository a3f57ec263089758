// The physical table-top of the independent generator: boxes built into a statically
// stable arrangement by construction (no physics engine): boxes on the table, boxes flush
// against a neighbour, stacks whose centre of mass lies over the supporter's top, and thin
// boxes leaning against a tall one. The relations (support, contact) are recorded as the
// construction makes them, not measured afterwards.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tools/tabletop_indep/geometry.h"

namespace ksmc::tools::tabletop_indep {

using Rng = std::mt19937_64;

inline constexpr int kTable = -1;  // the table in relation pairs

enum class Catalogue { household, wide };

struct WorldOptions {
  int min_boxes = 3, max_boxes = 8;
  double stack_rate = 0.35;   // share of boxes placed on another box
  double flush_rate = 0.25;   // share of table boxes placed flush against a neighbour
  double lean_rate = 0.0;     // share of boxes leaning against a tall box
  double hidden_rate = 0.3;   // chance per scene (repeated) that one carrying box goes undetected
  int max_hidden = 1;
  Catalogue catalogue = Catalogue::household;
  double region_x = 0.35, region_y = 0.28;  // half extents of the area boxes stand in, m
};

struct Body {
  Obb box;
  std::string label;           // catalogue class: "carton", "cube", "board", "bar", ...
  std::vector<int> rests_on;   // bodies (or kTable) under it; empty for a leaning box
  int leans_on = -2;           // the body a leaning box rests against
  bool undetected = false;     // no estimate of it (what hidden boxes stand on)
};

struct World {
  std::vector<Body> bodies;
  std::vector<std::pair<int, int>> contact;  // touching without support (a, b), b may be kTable
  bool carries_something(int i) const;       // something rests or leans on body i
  bool hidden(int i) const;                  // detected, and every body under it undetected
};

Eigen::Vector3d draw_size(Rng& rng, Catalogue catalogue, std::string& label);
World build_world(Rng& rng, const WorldOptions& options);

double uniform(Rng& rng, double lo, double hi);
int uniform_int(Rng& rng, int lo, int hi);  // inclusive
bool chance(Rng& rng, double p);

}  // namespace ksmc::tools::tabletop_indep
