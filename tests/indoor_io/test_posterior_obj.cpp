// posterior.png from stored samples only, and world.obj: a valid Wavefront OBJ with the walls
// extruded and a gap where a door is.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/io/posterior_plot.h"
#include "stdlib/indoor/io/world_images.h"
#include "stdlib/indoor/io/world_obj.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;

namespace {

std::array<Point2, 4> box(double x0, double y0, double x1, double y1) {
  return {Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}};
}

}  // namespace

TEST_CASE("posterior.png draws the stored samples, darker where they agree") {
  ClassGrid g(40, 60, static_cast<std::uint8_t>(Cell::Free));
  WorldResult w;
  CHECK_THROWS_WITH(render_posterior(g, w), Catch::Contains("no stored samples"));
  w.posterior = {{100, {box(5, 5, 30, 30)}}, {200, {box(5, 5, 30, 30)}}, {300, {box(5, 5, 40, 30)}}};
  const cv::Mat3b img = render_posterior(g, w);
  const int s = overlay_scale(40, 60);
  REQUIRE(img.cols == 60 * s);
  REQUIRE(img.rows > 40 * s);  // caption band
  // The left wall x = 5 is in all three samples, the right wall x = 40 in one: darker vs fainter red.
  const cv::Vec3b all = img(20 * s + s / 2, 5 * s + s / 2);
  const cv::Vec3b one = img(20 * s + s / 2, 40 * s + s / 2);
  CHECK(all[2] > all[0] + 100);
  CHECK(one[2] > one[0]);
  CHECK(one[0] > all[0]);
  CHECK(img(20 * s, 20 * s) == cv::Vec3b(255, 255, 255));  // free, no wall
}

TEST_CASE("world.obj: extruded walls with a door gap, valid OBJ") {
  WorldResult w;
  w.map.width = 60;
  w.map.height = 40;
  w.map.resolution = 0.1;
  w.map.origin = {1.0, 2.0, 0.0};
  w.wall_thickness = 1.0;
  w.units = {UnitResult{1, "", {}, box(10, 10, 30, 30)}, UnitResult{2, "", {}, box(30, 10, 50, 30)}};
  const std::string obj = world_obj_text(w, 2.5);
  std::istringstream in(obj);
  std::string line;
  int vertices = 0, faces = 0;
  double zmax = 0.0, xmin = 1e9, xmax = -1e9;
  bool valid = true;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      double x = 0, y = 0, z = 0;
      valid = valid && static_cast<bool>(ls >> x >> y >> z);
      zmax = std::max(zmax, z);
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
      ++vertices;
    } else if (tag == "f") {
      int n = 0, idx = 0;
      while (ls >> idx) {
        valid = valid && idx >= 1 && idx <= vertices;  // 1-based, defined before use
        ++n;
      }
      valid = valid && n >= 3;
      ++faces;
    } else {
      valid = valid && (tag.empty() || tag == "#" || tag == "o" || tag == "g");
    }
  }
  CHECK(valid);
  CHECK(zmax == Approx(2.5));
  // Metres in the map frame: x = origin.x + (col + 0.5) * resolution.
  CHECK(xmin == Approx(1.0 + 10.5 * 0.1));
  CHECK(xmax == Approx(1.0 + 50.5 * 0.1));
  const int walls_without_door = faces / 6;
  CHECK(walls_without_door == 8);  // 4 walls per unit, 6 faces per wall box
  // A door on the shared wall x = 30 from y = 15 to 20 cuts both units' walls there in two.
  w.doors = {DoorResult{1, 1, 2, {Point2{30, 15}, Point2{30, 20}}}};
  const std::string with_door = world_obj_text(w, 2.5);
  std::size_t door_faces = 0;
  for (std::size_t p = with_door.find("\nf "); p != std::string::npos; p = with_door.find("\nf ", p + 1)) ++door_faces;
  CHECK(door_faces == 10 * 6);
  CHECK(with_door.find("# door 1 cuts unit 1") != std::string::npos);
  CHECK(with_door.find("# door 1 cuts unit 2") != std::string::npos);
}
