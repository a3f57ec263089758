// FSU, RPB, split lines and door candidates on synthetic floor plans (also rotated).
#include <catch2/catch.hpp>

#include <chrono>
#include <iostream>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/detect/fsu.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/rpb.h"
#include "stdlib/indoor/detect/split.h"
#include "stdlib/indoor/detect/wbu.h"
#include "synthetic_map.h"
#include "tests/support/shared_data.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::detect;
using namespace ksmc::tests::indoor_detect;

namespace {

// Inside test of an oriented rectangle with a tolerance (cells).
bool contains(const OrientedRect& r, Point2 p, double tol = 0.0) {
  const double c = std::cos(r.theta), s = std::sin(r.theta);
  const double dx = p.x - r.cx, dy = p.y - r.cy;
  const double u = c * dx + s * dy, v = -s * dx + c * dy;
  return std::abs(u) <= 0.5 * r.w + tol && std::abs(v) <= 0.5 * r.h + tol;
}

double dist(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }
Point2 mid(Point2 a, Point2 b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

}  // namespace

TEST_CASE("FSU finds the free space the world does not explain", "[fsu]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 20.0, 33.0}) {
    const ClassGrid g = render(s, deg);
    // The world explains rooms A and B and the corridor; room C is left over.
    std::vector<OrientedRect> world;
    for (int k : {0, 1, 3}) world.push_back(expected_rect(s, s.rooms[k], deg));
    FsuParams fp;
    fp.frame_deg = deg;
    const auto cands = detect_fsu_units(g, raster(g, world), fp);
    INFO("deg " << deg << ": " << cands.size() << " FSU candidates");
    REQUIRE(!cands.empty());
    const OrientedRect want = expected_rect(s, s.rooms[2], deg);
    CHECK(iou(cands[0].rect, want) >= 0.8);
    CHECK(cands[0].weight >= 0.4);
    for (const auto& c : cands) CHECK(c.rect.area() < 0.3 * want.area() + (&c == &cands[0] ? 1e9 : 0.0));
    // minAreaRect mode agrees.
    const auto cands2 = detect_fsu_units(g, raster(g, world));
    REQUIRE(!cands2.empty());
    CHECK(iou(cands2[0].rect, want) >= 0.8);
  }
  // Nothing explained: the whole connected free space (rooms joined by doors) is one component.
  const ClassGrid g = render(s, 0.0);
  const auto all = detect_fsu_units(g, cv::Mat1b());
  REQUIRE(all.size() == 1);
  CHECK(contains(all[0].rect, {s.rooms[0].x0 + 5, s.rooms[0].y0 + 5}));
  CHECK(contains(all[0].rect, {s.rooms[3].x1 - 5, s.rooms[3].y1 - 5}));
  // Everything explained: no candidate.
  CHECK(detect_fsu_units(g, cv::Mat1b(g.size(), static_cast<unsigned char>(255))).empty());
  CHECK_THROWS_AS(detect_fsu_units(g, cv::Mat1b(3, 3, static_cast<unsigned char>(0))), std::invalid_argument);
}

TEST_CASE("RPB unit contains the robot and stays inside its room", "[rpb]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 20.0, 33.0}) {
    const ClassGrid g = render(s, deg);
    for (int k = 0; k < 4; ++k) {
      const Box& b = s.rooms[k];
      const Point2 robot_m{b.x0 + 0.3 * (b.x1 - b.x0), b.y0 + 0.6 * (b.y1 - b.y0)};
      const Point2 robot = expected_point(s, robot_m, deg);
      RpbParams rp;
      rp.frame_deg = deg;
      rp.max_half_extent = 1000;
      const auto u = detect_rpb_unit(g, robot, rp);
      INFO("room " << k << " deg " << deg);
      REQUIRE(u.has_value());
      CHECK(contains(u->rect, robot));
      const OrientedRect room = expected_rect(s, b, deg);
      for (const auto& c : u->rect.corners()) CHECK(contains(room, c, 2.0));
      // Grown until the walls: it covers most of the room.
      CHECK(iou(u->rect, room) >= 0.8);
      CHECK(u->weight > 0.4);
      // A capped unit is small but still around the robot.
      rp.max_half_extent = 8;
      const auto small = detect_rpb_unit(g, robot, rp);
      REQUIRE(small.has_value());
      CHECK(contains(small->rect, robot));
      CHECK(small->rect.w <= 18.5);
      CHECK(small->rect.h <= 18.5);
    }
    // Robot on a wall or outside the map: nothing.
    const Point2 on_wall = expected_point(s, {s.rooms[0].x0 + 30, s.rooms[0].y0}, deg);
    RpbParams rp;
    rp.frame_deg = deg;
    CHECK_FALSE(detect_rpb_unit(g, on_wall, rp).has_value());
    CHECK_FALSE(detect_rpb_unit(g, {-5, 3}, rp).has_value());
  }
}

TEST_CASE("split lines are found at an internal wall", "[split]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 20.0, 33.0}) {
    const ClassGrid g = render(s, deg);
    // A unit covering rooms A and B (wall at model x = ox + 100 inside it).
    const Box& a = s.rooms[0];
    const Box& b = s.rooms[1];
    const OrientedRect ab = expected_rect(s, Box{a.x0, a.y0, b.x1, b.y1}, deg);
    const auto lines = detect_split_lines(g, ab);
    INFO("deg " << deg << ": " << lines.size() << " split lines");
    REQUIRE(!lines.empty());
    // The strongest is the A|B wall; it runs from the top wall to the bottom wall.
    const Point2 top = expected_point(s, {a.x1, a.y0}, deg), bottom = expected_point(s, {a.x1, a.y1}, deg);
    const auto& l = lines[0];
    const bool fwd = dist(l.a, top) < 2.5 && dist(l.b, bottom) < 2.5;
    const bool rev = dist(l.b, top) < 2.5 && dist(l.a, bottom) < 2.5;
    CHECK((fwd || rev));
    CHECK(l.weight >= 50.0);  // most of the 100-cell wall (minus door and margins) is covered
    // Inside a single room there is nothing to split.
    CHECK(detect_split_lines(g, expected_rect(s, s.rooms[2], deg)).empty());
  }
  CHECK_THROWS_AS(detect_split_lines(render(s, 0), OrientedRect{10, 10, 0, 5, 0}), std::invalid_argument);
}

TEST_CASE("door candidates at every drawn doorway and none on a solid wall", "[door]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 20.0, 33.0})
  for (double inset : {0.0, 2.0}) {  // units on the wall centre lines, or on the wall faces
    const ClassGrid g = render(s, deg);
    std::vector<OrientedRect> units;
    for (const auto& r : s.rooms) {
      units.push_back(expected_rect(s, r, deg));
      units.back().w -= 2 * inset;
      units.back().h -= 2 * inset;
    }
    const auto doors = detect_doors(g, units);
    INFO("deg " << deg << " inset " << inset << ": " << doors.size() << " door candidates");
    // Each drawn doorway has a candidate whose centre is within 3 cells.
    for (const auto& d : s.doors) {
      const Point2 want = expected_point(s, {0.5 * (d.x0 + d.x1), 0.5 * (d.y0 + d.y1)}, deg);
      double best = 1e9;
      for (const auto& c : doors) best = std::min(best, dist(mid(c.a, c.b), want));
      INFO("door at model " << d.x0 << "," << d.y0 << ": nearest candidate " << best);
      CHECK(best <= 3.0);
    }
    // Every candidate is at a drawn doorway (none on the solid B|C wall or elsewhere),
    // between the right units, with a sensible width and weight.
    for (const auto& c : doors) {
      double best = 1e9;
      for (const auto& d : s.doors)
        best = std::min(best, dist(mid(c.a, c.b), expected_point(s, {0.5 * (d.x0 + d.x1), 0.5 * (d.y0 + d.y1)}, deg)));
      CHECK(best <= 3.0);
      CHECK(dist(c.a, c.b) >= 8.0);
      CHECK(dist(c.a, c.b) <= 18.0);
      CHECK(c.weight >= 0.6);
      CHECK(c.unit_a < c.unit_b);
      CHECK_FALSE((c.unit_a == 1 && c.unit_b == 2));  // B|C wall is solid
    }
    CHECK(doors.size() == s.doors.size());
  }
  CHECK(detect_doors(render(s, 0), {}).empty());
  CHECK_THROWS_AS(detect_doors(render(s, 0), {OrientedRect{1, 1, -1, 1, 0}}), std::invalid_argument);
}

TEST_CASE("real maps: FSU, RPB, split and doors on WBU output", "[real]") {
  const std::string dir = "data/maps/bormann_ipa/test_maps/";
  for (const char* name : {"lab_b_scan.png", "Freiburg52_scan.png"}) {
    if (!ksmc::tests::have_shared(dir + name)) continue;
    const ClassGrid g = load_png_map((ksmc::tests::shared_dir() / (dir + name)).string(), true);
    const auto t0 = std::chrono::steady_clock::now();
    const auto wbu = detect_wbu_units(g);
    REQUIRE(!wbu.candidates.empty());
    // A toy world: greedily take strong, room-sized, non-overlapping WBU candidates.
    std::vector<OrientedRect> world;
    for (const auto& c : wbu.candidates) {
      bool clash = c.rect.area() > 0.05 * g.total();
      for (const auto& w : world) clash = clash || iou(c.rect, w) > 0.0;
      if (!clash) world.push_back(c.rect);
      if (world.size() >= 12) break;
    }
    FsuParams fp;
    fp.frame_deg = wbu.frames_deg[0];
    const auto fsu = detect_fsu_units(g, raster(g, world), fp);
    std::size_t nsplit = 0;
    for (const auto& w : world) nsplit += detect_split_lines(g, w).size();
    const auto doors = detect_doors(g, world);
    RpbParams rp;
    rp.frame_deg = wbu.frames_deg[0];
    const auto rpb = detect_rpb_unit(g, {world[0].cx, world[0].cy}, rp);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << name << ": world of " << world.size() << " units, " << fsu.size() << " FSU, " << nsplit
              << " split lines, " << doors.size() << " doors, RPB " << (rpb ? "yes" : "no") << ", " << sec << " s\n";
    CHECK(fsu.size() >= 1);
    CHECK(doors.size() <= 4 * world.size());
    for (const auto& d : doors) CHECK(d.weight >= 0.0);
    CHECK(sec < 5.0);
  }
}

TEST_CASE("detectors are deterministic and survive units reaching outside the map", "[door][split][fsu]") {
  const Scene s = office_scene();
  const ClassGrid g = render(s, 20.0);
  std::vector<OrientedRect> units;
  for (const auto& r : s.rooms) units.push_back(expected_rect(s, r, 20.0));
  const auto d1 = detect_doors(g, units), d2 = detect_doors(g, units);
  REQUIRE(d1.size() == d2.size());
  for (std::size_t i = 0; i < d1.size(); ++i) {
    CHECK(d1[i].a.x == d2[i].a.x);
    CHECK(d1[i].b.y == d2[i].b.y);
    CHECK(d1[i].weight == d2[i].weight);
  }
  // A unit hanging far over the map border and a huge one: no crash, sensible output.
  const OrientedRect outside{-50, -40, 200, 150, 0.3};
  const OrientedRect huge{100, 100, 1e5, 1e5, 0.1};
  CHECK_NOTHROW(detect_split_lines(g, outside));
  CHECK_NOTHROW(detect_split_lines(g, huge));
  units.push_back(outside);
  CHECK_NOTHROW(detect_doors(g, units));
  RpbParams rp;
  rp.frame_deg = 20.0;
  const Point2 robot = expected_point(s, {s.rooms[3].x0 + 10, s.rooms[3].y0 + 20}, 20.0);
  const auto r1 = detect_rpb_unit(g, robot, rp), r2 = detect_rpb_unit(g, robot, rp);
  REQUIRE(r1.has_value());
  CHECK(r1->rect.cx == r2->rect.cx);
  CHECK(r1->rect.w == r2->rect.w);
}
