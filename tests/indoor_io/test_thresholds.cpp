// The default thresholds of bare images (Thresholds::drawn): >= 250 free, dark occupied, and of
// the greys between, the one painting >= 5 % of the image unknown, the others occupied. Drawn
// plans (grey walls on a grey outside) and SLAM images (one light grey for unexplored space)
// both read right; on Freiburg52_scan (grey walls) the walls are occupied, not unknown.
#include <catch2/catch.hpp>

#include <opencv2/core.hpp>

#include "stdlib/indoor/io/map_loader.h"
#include "tests/support/shared_data.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;

namespace {

std::uint8_t cls(Cell c) { return static_cast<std::uint8_t>(c); }

}  // namespace

TEST_CASE("drawn thresholds: the painted grey is unknown, other greys are occupied") {
  // A drawn plan: outside grey 180 (most of the image), a free room 255, walls in greys 120 and
  // 211 and black, one near-white 252 pixel.
  cv::Mat1b img(20, 20, static_cast<std::uint8_t>(180));
  img(cv::Rect(4, 4, 12, 12)).setTo(120);
  img(cv::Rect(5, 5, 10, 10)).setTo(255);
  img(4, 8) = 211;
  img(4, 9) = 0;
  img(6, 6) = 252;
  const ClassGrid g = classify_image(img, Thresholds::drawn());
  CHECK(g(0, 0) == cls(Cell::Unknown));   // the paint
  CHECK(g(4, 4) == cls(Cell::Occupied));  // grey wall
  CHECK(g(4, 8) == cls(Cell::Occupied));  // light grey wall (map_server would call 211 free)
  CHECK(g(4, 9) == cls(Cell::Occupied));
  CHECK(g(6, 6) == cls(Cell::Free));
  CHECK(g(10, 10) == cls(Cell::Free));
  // strict reads every grey as unknown, so the room has no walls.
  ImageLoadOptions strict;
  strict.thresholds.free_thresh = 5.5 / 255.0;
  CHECK(classify_image(img, strict.thresholds)(4, 4) == cls(Cell::Unknown));
}

TEST_CASE("drawn thresholds: a SLAM image keeps its unexplored grey unknown; no paint, no unknown") {
  cv::Mat1b slam(20, 20, static_cast<std::uint8_t>(205));  // map_saver: 205 unknown, 254 free, 0 wall
  slam(cv::Rect(2, 2, 10, 10)).setTo(254);
  slam(cv::Rect(2, 1, 10, 1)).setTo(0);
  slam(12, 5) = 150;  // a lone mid grey: an obstacle's edge
  const ClassGrid g = classify_image(slam, Thresholds::drawn());
  CHECK(g(15, 15) == cls(Cell::Unknown));
  CHECK(g(5, 5) == cls(Cell::Free));
  CHECK(g(1, 5) == cls(Cell::Occupied));
  CHECK(g(12, 5) == cls(Cell::Occupied));
  // A grey under 5 % of the image is not paint: every grey is occupied.
  cv::Mat1b plan(20, 20, static_cast<std::uint8_t>(255));
  plan(cv::Rect(0, 0, 20, 1)).setTo(180);  // 20 of 400 pixels = 5 %: paint
  CHECK(classify_image(plan, Thresholds::drawn())(0, 0) == cls(Cell::Unknown));
  plan(0, 0) = 255;  // 19 of 400: a wall
  CHECK(classify_image(plan, Thresholds::drawn())(0, 1) == cls(Cell::Occupied));
}

TEST_CASE("drawn thresholds on Freiburg52_scan: the grey walls are occupied") {
  const std::string rel = "data/maps/bormann_ipa/test_maps/Freiburg52_scan.png";
  if (!ksmc::tests::have_shared(rel)) return;
  ImageLoadOptions drawn, bormann;
  drawn.thresholds = Thresholds::drawn();
  bormann.thresholds = Thresholds::bormann();
  const ClassCounts d = load_map_image(ksmc::tests::shared_dir() / rel, drawn).counts();
  const ClassCounts b = load_map_image(ksmc::tests::shared_dir() / rel, bormann).counts();
  CHECK(d.free == b.free);
  // All but the outside paint (grey 180, 57,536 pixels) is occupied; strict had 1,539 occupied.
  CHECK(d.unknown == 57536);
  CHECK(d.occupied == b.occupied - 57536);
}
