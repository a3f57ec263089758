// A scene the generator cannot make: both rounds of draws are spent, and the error says why.
#include <catch2/catch.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "tools/tabletop_sim/generator.h"
#include "tools/tabletop_sim/layout.h"

using namespace ksmc::tools::tabletop_sim;

TEST_CASE("The second round of draws widens the drop region by half, within the table", "[tabletop_sim][generator]") {
  TableSpec table;  // 1.2 x 0.8 m
  const Eigen::Vector2d usual = drop_region(10, table);
  const Eigen::Vector2d wide = drop_region(10, table, 1.5);
  CHECK(wide.x() == Approx(1.5 * usual.x()));
  CHECK(wide.y() == Approx(std::min(1.5 * usual.y(), table.half_extent.y() - 0.08)));
  CHECK(drop_region(25, table, 1.5).x() <= table.half_extent.x() - 0.08);
}

TEST_CASE("A table too small for the boxes fails after both rounds, each reason counted", "[tabletop_sim][generator]") {
  GeneratorOptions o;
  o.min_objects = o.max_objects = 4;
  o.max_attempts = 2;
  o.table.half_extent = Eigen::Vector2d(0.09, 0.09);  // a drop region 1 cm wide: nothing fits
  try {
    (void)generate_scene(5, o);
    FAIL("generate_scene made a scene on a table too small for it");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("no valid scene after 4 draws (4 x could not place 4 boxes without overlap)") != std::string::npos);
  }
}
