// Orientation, cumulative sampler, wall weights and the WBU detector.
#include <catch2/catch.hpp>

#include <chrono>
#include <iostream>
#include <random>

#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/sampler.h"
#include "stdlib/indoor/detect/wall_score.h"
#include "stdlib/indoor/detect/wbu.h"
#include "synthetic_map.h"
#include "tests/support/shared_data.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::detect;
using namespace ksmc::tests::indoor_detect;

TEST_CASE("dominant orientation of synthetic maps is recovered within 1 degree", "[orientation]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 7.0, 20.0, 33.0, -25.0}) {
    const auto o = dominant_orientation(render(s, deg));
    INFO("drawn at " << deg << " deg, found " << o.angle_deg << " conf " << o.confidence);
    CHECK(angle_diff_mod90(o.angle_deg, deg) < 1.0);
    CHECK(o.angle_deg >= 0.0);
    CHECK(o.angle_deg < 90.0);
    CHECK(o.confidence > 0.7);
  }
}

TEST_CASE("orientation of an empty map has zero confidence; bad grids are rejected", "[orientation]") {
  ClassGrid g(50, 50, static_cast<unsigned char>(Cell::Free));
  const auto o = dominant_orientation(g);
  CHECK(o.confidence == 0.0);
  ClassGrid bad(10, 10, static_cast<unsigned char>(7));
  CHECK_THROWS_WITH(dominant_orientation(bad), Catch::Contains("not a Cell"));
  CHECK_THROWS_AS(dominant_orientation(ClassGrid()), std::invalid_argument);
}

TEST_CASE("orientations_of finds a secondary orientation", "[orientation]") {
  std::vector<Segment> segs;
  for (int i = 0; i < 10; ++i) segs.push_back({{0, double(i * 10)}, {100, double(i * 10)}});  // 0 deg
  const double a = 30.0 * 3.14159265358979 / 180.0;
  for (int i = 0; i < 4; ++i)
    segs.push_back({{0, double(i * 10)}, {80 * std::cos(a), i * 10 + 80 * std::sin(a)}});  // 30 deg
  const auto peaks = orientations_of(segs, {});
  REQUIRE(peaks.size() >= 2);
  CHECK(angle_diff_mod90(peaks[0].angle_deg, 0.0) < 0.5);
  CHECK(angle_diff_mod90(peaks[1].angle_deg, 30.0) < 0.5);
  CHECK(peaks[0].confidence > peaks[1].confidence);
}

TEST_CASE("cumulative sampler follows eq. 3.15-3.17", "[sampler]") {
  const CumulativeSampler s({1.0, 0.0, 3.0});
  CHECK(s.probability(0) == Approx(0.25));
  CHECK(s.probability(1) == 0.0);
  CHECK(s.log_probability(2) == Approx(std::log(0.75)));
  CHECK(std::isinf(s.log_probability(1)));
  CHECK(s.draw(0.0).index == 0);
  CHECK(s.draw(0.2499).index == 0);
  CHECK(s.draw(0.25).index == 2);  // zero-weight candidate is never drawn
  CHECK(s.draw(0.999999).index == 2);
  CHECK(s.draw(0.5).probability == Approx(0.75));

  std::mt19937_64 rng(42);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 40000; ++i) ++counts[s.sample(rng).index];
  CHECK(counts[1] == 0);
  CHECK(counts[0] / 40000.0 == Approx(0.25).margin(0.01));

  std::mt19937_64 r1(7), r2(7);
  for (int i = 0; i < 100; ++i) CHECK(s.sample(r1).index == s.sample(r2).index);

  CHECK(CumulativeSampler({0.0, 0.0}).empty());
  CHECK_THROWS_AS(CumulativeSampler({0.0}).draw(0.1), std::logic_error);
  CHECK_THROWS_AS(CumulativeSampler({1.0, -1.0}), std::invalid_argument);
  CHECK_THROWS_AS(s.draw(1.0), std::invalid_argument);
}

TEST_CASE("wall, unit and door weights (eq. 3.10-3.14, 3.23-3.25)", "[weights]") {
  ClassGrid g(40, 40, static_cast<unsigned char>(Cell::Free));
  cv::line(g, {5, 10}, {34, 10}, cv::Scalar(double(Cell::Occupied)));  // 30 cells
  CHECK(wall_weight(g, {5, 10}, {34, 10}) == Approx(1.0));
  CHECK(wall_weight(g, {5, 12}, {34, 12}) == Approx(1.0));        // within the default tolerance 2
  CHECK(wall_weight(g, {5, 13}, {34, 13}) == Approx(0.0));        // beyond it
  CHECK(wall_weight(g, {5, 11}, {34, 11}, {0}) == Approx(0.0));   // exact eq. 3.14
  CHECK(wall_weight(g, {5, 10}, {64, 10}) == Approx(0.5));        // half of it outside the map / free
  CHECK(door_weight(g, {5, 20}, {34, 20}) == Approx(1.0));
  CHECK(door_weight(g, {5, 10}, {34, 10}) == Approx(0.0));
  CHECK(door_weight(g, {5, 12}, {34, 12}, {3}) == Approx(0.0));   // wall within the probe
  const OrientedRect r{20, 20, 29, 20, 0.0};                        // top side on the drawn line
  CHECK(unit_weight(g, r) == Approx(0.0));                          // other sides free
}

TEST_CASE("WBU candidates include every drawn room, also rotated", "[wbu]") {
  const Scene s = office_scene();
  for (double deg : {0.0, 20.0, 33.0}) {
    const ClassGrid g = render(s, deg);
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = detect_wbu_units(g);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "WBU synthetic " << deg << " deg: " << res.candidates.size() << " candidates, "
              << res.frames_deg.size() << " frames, " << ms << " ms\n";
    REQUIRE(!res.candidates.empty());
    REQUIRE(res.sampler.size() == res.candidates.size());
    CHECK(angle_diff_mod90(res.frames_deg[0], deg) < 1.0);
    for (std::size_t i = 1; i < res.candidates.size(); ++i)
      CHECK(res.candidates[i - 1].weight >= res.candidates[i].weight);
    for (const auto& room : s.rooms) {
      const OrientedRect want = expected_rect(s, room, deg);
      double best = 0.0, best_w = 0.0;
      for (const auto& c : res.candidates) {
        const double v = iou(c.rect, want);
        if (v > best) best = v, best_w = c.weight;
      }
      INFO("room " << room.x0 << "," << room.y0 << " at " << deg << " deg: best IoU " << best);
      CHECK(best >= 0.8);
      CHECK(best_w >= 0.6);
    }
    // A rectangle straddling the solid outer wall into unknown space is never proposed.
    for (const auto& c : res.candidates) CHECK(c.weight <= 1.0);
    // Determinism.
    const auto again = detect_wbu_units(g);
    REQUIRE(again.candidates.size() == res.candidates.size());
    for (std::size_t i = 0; i < res.candidates.size(); ++i) {
      CHECK(again.candidates[i].rect.cx == res.candidates[i].rect.cx);
      CHECK(again.candidates[i].weight == res.candidates[i].weight);
    }
  }
}

TEST_CASE("real maps: orientation and WBU smoke test", "[wbu][real]") {
  const std::string dir = "data/maps/bormann_ipa/test_maps/";
  if (ksmc::tests::have_shared(dir + "lab_b.png")) {
    const ClassGrid g = load_png_map((ksmc::tests::shared_dir() / (dir + "lab_b.png")).string(), false);
    const auto o = dominant_orientation(g);
    std::cout << "lab_b.png " << g.cols << "x" << g.rows << ": orientation " << o.angle_deg << " deg, confidence "
              << o.confidence << "\n";
    // The corridor runs from about (150, 540) to (1140, 95): atan2(-445, 990) = -24.2 deg.
    CHECK(angle_diff_mod90(o.angle_deg, -24.2) < 1.5);
    CHECK(o.confidence > 0.5);
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = detect_wbu_units(g);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "lab_b.png WBU: " << res.candidates.size() << " candidates (" << res.enumerated << " enumerated), "
              << res.wall_lines.size() << " wall lines, " << s << " s\n";
    CHECK(res.candidates.size() >= 20);
    CHECK(s < 5.0);
  }
  for (const char* name : {"lab_b_scan.png", "Freiburg52_scan.png", "office_g.png"}) {
    if (!ksmc::tests::have_shared(dir + name)) continue;
    const ClassGrid g = load_png_map((ksmc::tests::shared_dir() / (dir + name)).string(), true);
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = detect_wbu_units(g);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << name << " " << g.cols << "x" << g.rows << ": frame " << res.frames_deg[0] << " deg, "
              << res.candidates.size() << " WBU candidates (" << res.enumerated << " enumerated), " << s << " s\n";
    CHECK(res.candidates.size() >= 10);
    CHECK(s < 5.0);
  }
}

TEST_CASE("WBU also works in a second strong orientation", "[wbu]") {
  // Two buildings on one canvas: a big room at 0 deg and a smaller one rotated by 30 deg.
  Scene s1, s2;
  s1.cols = s2.cols = 500;
  s1.rows = s2.rows = 400;
  s1.rooms = {{40, 100, 200, 300}};
  s1.walls = {{40, 100, 200, 100}, {40, 300, 200, 300}, {40, 100, 40, 300}, {200, 100, 200, 300}};
  s2.rooms = {{300, 150, 400, 250}};
  s2.walls = {{300, 150, 400, 150}, {300, 250, 400, 250}, {300, 150, 300, 250}, {400, 150, 400, 250}};
  const ClassGrid g1 = render(s1, 0.0), g2 = render(s2, 30.0);
  ClassGrid g(g1.size(), static_cast<unsigned char>(Cell::Unknown));
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const auto a = Cell(g1(r, c)), b = Cell(g2(r, c));
      if (a == Cell::Occupied || b == Cell::Occupied) g(r, c) = static_cast<unsigned char>(Cell::Occupied);
      else if (a == Cell::Free || b == Cell::Free) g(r, c) = static_cast<unsigned char>(Cell::Free);
    }

  const auto res = detect_wbu_units(g);
  REQUIRE(res.frames_deg.size() >= 2);
  CHECK(angle_diff_mod90(res.frames_deg[0], 0.0) < 1.0);
  CHECK(angle_diff_mod90(res.frames_deg[1], 30.0) < 1.0);
  for (const auto& [scene, deg] : {std::pair{&s1, 0.0}, std::pair{&s2, 30.0}}) {
    const OrientedRect want = expected_rect(*scene, scene->rooms[0], deg);
    double best = 0.0;
    for (const auto& c : res.candidates) best = std::max(best, iou(c.rect, want));
    INFO("room at " << deg << " deg: best IoU " << best);
    CHECK(best >= 0.8);
  }
  // Without secondary orientations the rotated room is missed.
  WbuParams only_dominant;
  only_dominant.secondary_orientations = false;
  const auto res1 = detect_wbu_units(g, only_dominant);
  REQUIRE(res1.frames_deg.size() == 1);
  double best = 0.0;
  for (const auto& c : res1.candidates) best = std::max(best, iou(c.rect, expected_rect(s2, s2.rooms[0], 30.0)));
  CHECK(best < 0.8);
}

TEST_CASE("WBU rejects bad parameters", "[wbu]") {
  const ClassGrid g = render(office_scene(), 0.0);
  WbuParams p;
  p.min_side = 0;
  CHECK_THROWS_AS(detect_wbu_units(g, p), std::invalid_argument);
  p = {};
  p.max_candidates = 3;
  const auto res = detect_wbu_units(g, p);
  CHECK(res.candidates.size() == 3);
  CHECK(res.enumerated >= 3);
}
