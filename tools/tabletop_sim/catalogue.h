// Catalogue of household box-like products with realistic dimension ranges.
// Sizes are full extents in metres in the product's own frame: x = width, y = depth,
// z = height as it stands on a shelf.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include <Eigen/Core>

#include "tools/tabletop_sim/random.h"

namespace ksmc::tools::tabletop_sim {

struct Product {
  std::string_view name;
  Eigen::Vector3d min_size;
  Eigen::Vector3d max_size;
  double min_density;  // kg/m^3 of the bounding box (a half-empty cereal box is light)
  double max_density;
  // Relative odds of resting on the table with local axis x, y or z vertical.
  std::array<double, 3> vertical_axis_odds;
  double friction;
};

// A drawn instance of a product.
struct BoxItem {
  std::string_view model;
  Eigen::Vector3d size;  // full extents, metres
  double mass = 0.0;     // kg
  double friction = 0.5;
  std::array<double, 3> vertical_axis_odds{1.0, 1.0, 1.0};
};

// Which products a scene draws from: the household boxes, or those plus objects from 2 cm
// to 40 cm (dice and cubes, thin boards and cases, shoe boxes, long boxes).
enum class Catalogue { household, wide };

std::span<const Product> product_catalogue(Catalogue catalogue = Catalogue::household);

// Draws a product uniformly from the catalogue, then its size and density. A product whose
// minimum and maximum sizes are both cubes (equal extents) draws one edge: a cube.
BoxItem draw_box(Rng& rng, Catalogue catalogue = Catalogue::household);

}  // namespace ksmc::tools::tabletop_sim
