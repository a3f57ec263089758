#include "tools/tabletop_sim/catalogue.h"

namespace ksmc::tools::tabletop_sim {

namespace {
using V = Eigen::Vector3d;

// Ranges from common European retail packaging (measured on shelves and manufacturer sheets).
const std::array<Product, 22> kCatalogue{{
    {"cereal", V(0.19, 0.055, 0.26), V(0.23, 0.080, 0.33), 110, 190, {0.0, 0.45, 0.55}, 0.55},
    {"milk_carton", V(0.060, 0.060, 0.17), V(0.095, 0.072, 0.245), 800, 950, {0.1, 0.2, 0.7}, 0.5},
    {"juice_box", V(0.040, 0.030, 0.090), V(0.065, 0.045, 0.125), 800, 950, {0.1, 0.3, 0.6}, 0.5},
    {"tea_box", V(0.120, 0.060, 0.060), V(0.160, 0.085, 0.080), 90, 200, {0.1, 0.3, 0.6}, 0.55},
    {"book", V(0.130, 0.190, 0.015), V(0.210, 0.300, 0.050), 450, 750, {0.05, 0.1, 0.85}, 0.45},
    {"cookie_box", V(0.180, 0.050, 0.045), V(0.220, 0.070, 0.065), 180, 320, {0.0, 0.3, 0.7}, 0.55},
    {"cream_cheese", V(0.090, 0.055, 0.025), V(0.110, 0.070, 0.035), 500, 800, {0.0, 0.0, 1.0}, 0.5},
    {"pasta_box", V(0.100, 0.040, 0.180), V(0.130, 0.060, 0.250), 250, 380, {0.05, 0.45, 0.5}, 0.55},
    {"toothpaste", V(0.170, 0.035, 0.030), V(0.210, 0.045, 0.045), 250, 400, {0.0, 0.3, 0.7}, 0.5},
    {"sugar_box", V(0.090, 0.060, 0.140), V(0.120, 0.080, 0.180), 750, 900, {0.05, 0.25, 0.7}, 0.6},
    {"tissue_box", V(0.220, 0.110, 0.070), V(0.250, 0.130, 0.100), 50, 110, {0.0, 0.1, 0.9}, 0.5},
    {"butter", V(0.100, 0.060, 0.030), V(0.130, 0.072, 0.042), 850, 950, {0.0, 0.1, 0.9}, 0.45},
    {"rice_box", V(0.110, 0.050, 0.160), V(0.140, 0.070, 0.220), 600, 850, {0.05, 0.45, 0.5}, 0.55},
    {"medicine_box", V(0.080, 0.020, 0.050), V(0.130, 0.050, 0.080), 150, 350, {0.05, 0.45, 0.5}, 0.5},
    // The wide catalogue adds these (2 cm to 40 cm, cubes and thin boxes).
    {"dice", V(0.020, 0.020, 0.020), V(0.032, 0.032, 0.032), 600, 1100, {1.0, 1.0, 1.0}, 0.5},
    {"cube", V(0.040, 0.040, 0.040), V(0.090, 0.090, 0.090), 150, 500, {1.0, 1.0, 1.0}, 0.5},
    {"big_cube", V(0.150, 0.150, 0.150), V(0.240, 0.240, 0.240), 40, 120, {1.0, 1.0, 1.0}, 0.55},
    {"thin_board", V(0.150, 0.100, 0.006), V(0.400, 0.300, 0.014), 450, 700, {0.0, 0.0, 1.0}, 0.45},
    {"cd_case", V(0.120, 0.120, 0.008), V(0.145, 0.128, 0.011), 600, 900, {0.0, 0.0, 1.0}, 0.35},
    {"matchbox", V(0.045, 0.030, 0.012), V(0.058, 0.038, 0.018), 200, 400, {0.0, 0.2, 0.8}, 0.5},
    {"shoe_box", V(0.280, 0.170, 0.095), V(0.360, 0.220, 0.130), 40, 110, {0.0, 0.0, 1.0}, 0.55},
    {"long_box", V(0.300, 0.050, 0.045), V(0.400, 0.090, 0.080), 100, 300, {0.0, 0.3, 0.7}, 0.5},
}};
constexpr std::size_t kHousehold = 14;

bool is_cube(const Product& p) {
  return p.min_size.x() == p.min_size.y() && p.min_size.y() == p.min_size.z() && p.max_size.x() == p.max_size.y() &&
         p.max_size.y() == p.max_size.z();
}
}  // namespace

std::span<const Product> product_catalogue(Catalogue catalogue) {
  const std::span<const Product> all(kCatalogue);
  return catalogue == Catalogue::household ? all.first(kHousehold) : all;
}

BoxItem draw_box(Rng& rng, Catalogue catalogue) {
  const auto products = product_catalogue(catalogue);
  const auto& p = products[static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(products.size()) - 1))];
  BoxItem b;
  b.model = p.name;
  if (is_cube(p)) {
    b.size.setConstant(rng.uniform(p.min_size.x(), p.max_size.x()));
  } else {
    for (int i = 0; i < 3; ++i) b.size[i] = rng.uniform(p.min_size[i], p.max_size[i]);
  }
  b.mass = rng.uniform(p.min_density, p.max_density) * b.size.prod();
  b.friction = p.friction;
  b.vertical_axis_odds = p.vertical_axis_odds;
  return b;
}

}  // namespace ksmc::tools::tabletop_sim
