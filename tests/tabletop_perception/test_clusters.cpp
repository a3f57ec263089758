// Clustering the points above the table: a flat top seen at a slant is sampled in rows
// farther apart than the tolerance along the ray's direction; joined along the rows
// (ClusterOptions::slant_factor), it is one cluster, while gaps across the view and gaps
// longer than the rows' spacing still separate.
#include <catch2/catch.hpp>

#include "stdlib/tabletop/perception/clusters.h"

using namespace ksmc::stdlib::tabletop::perception;

namespace {

// A flat top at height z: rows along x (3 mm apart within a row), `row_gap` apart in y.
void add_rows(Points& pts, double x0, double x1, double y0, double y1, double z, double row_gap) {
  for (double y = y0; y <= y1 + 1e-9; y += row_gap)
    for (double x = x0; x <= x1 + 1e-9; x += 0.003) pts.emplace_back(x, y, z);
}

const Eigen::Vector3d kSensor(0.0, -1.0, 0.4);  // looking along +y, 35 cm above the tops
const Eigen::Vector2d kTable(1.2, 0.8);

std::size_t count(const Points& pts, double slant_factor) {
  ClusterOptions o;
  o.slant_factor = slant_factor;
  return AboveTable(pts, kTable, o).clusters(o, kSensor).size();
}

}  // namespace

TEST_CASE("clusters: a grazing top sampled in rows 14 mm apart is one cluster", "[perception][clusters]") {
  Points pts;
  add_rows(pts, -0.1, 0.1, 0.1, 0.3, 0.05, 0.014);
  CHECK(count(pts, 2.0) == 1);
  // With the tolerance alone (8 mm), every row is a cluster of its own.
  CHECK(count(pts, 0.0) == 15);
  // Without a sensor the overload is isotropic whatever slant_factor says.
  ClusterOptions o;
  CHECK(AboveTable(pts, kTable, o).clusters(o).size() == 15);
}

TEST_CASE("clusters: gaps across the view, and longer than the rows' spacing, still separate", "[perception][clusters]") {
  Points across;  // two tops side by side, 15 mm apart in x (across the view)
  add_rows(across, -0.1, -0.0075, 0.1, 0.3, 0.05, 0.014);
  add_rows(across, 0.0075, 0.1, 0.1, 0.3, 0.05, 0.014);
  CHECK(count(across, 2.0) == 2);
  Points along;  // two tops one behind the other, 40 mm apart in y (along the view)
  add_rows(along, -0.1, 0.1, 0.1, 0.2, 0.05, 0.014);
  add_rows(along, -0.1, 0.1, 0.24, 0.34, 0.05, 0.014);
  CHECK(count(along, 2.0) == 2);
  Points above;  // two tops 14 mm apart in height: the rest of the offset is held to the tolerance
  add_rows(above, -0.1, 0.1, 0.1, 0.2, 0.05, 0.014);
  add_rows(above, -0.1, 0.1, 0.21, 0.3, 0.064, 0.014);
  CHECK(count(above, 2.0) == 2);
}

TEST_CASE("clusters: points straight below the sensor (no ray direction) join by the tolerance", "[perception][clusters]") {
  // One row of points along x through the sensor's foot: the pairs across it have opposite
  // horizontal ray directions, so no direction of their own.
  Points pts;
  add_rows(pts, -0.1215, 0.1215, 0.0, 0.0, 0.05, 0.01);
  ClusterOptions o;
  CHECK(AboveTable(pts, kTable, o).clusters(o, Eigen::Vector3d(0.0, 0.0, 1.0)).size() == 1);
}
