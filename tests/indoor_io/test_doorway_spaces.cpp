// segmentation.png: free space no unit explains, reached by the fill only through a doorway, is
// a space of its own (stdlib/indoor/io/doorway_spaces.h); a part of a room a unit missed, open
// to the unit over more than a door, stays the unit's.
#include <catch2/catch.hpp>

#include "stdlib/indoor/io/segmentation.h"
#include "tests/indoor_io/axis_unit.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::indoor_io::kFree;
using ksmc::tests::indoor_io::kOcc;
using ksmc::tests::indoor_io::unit;

namespace {

// Two offices (rows 2..61, cols 2..79 and 82..161, a wall at cols 80-81 between them) above a
// 1 m corridor (rows 64..83) behind a wall at rows 62-63, each office with a 1 m door (cols
// 30..49 and 110..129). 0.05 m cells.
ClassGrid offices_over_corridor() {
  ClassGrid g(86, 164, kOcc);
  for (int r = 2; r <= 61; ++r)
    for (int c = 2; c <= 161; ++c)
      if (c != 80 && c != 81) g(r, c) = kFree;
  for (int r = 64; r <= 83; ++r)
    for (int c = 2; c <= 161; ++c) g(r, c) = kFree;
  for (int r = 62; r <= 63; ++r)
    for (int c = 30; c <= 49; ++c) g(r, c) = g(r, c + 80) = kFree;
  return g;
}

}  // namespace

TEST_CASE("segmentation: a corridor no unit covers, behind the offices' doors, is one space of its own") {
  const ClassGrid g = offices_over_corridor();
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(3, 1.5, 1.5, 79.5, 61.5), unit(4, 81.5, 1.5, 161.5, 61.5)};
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(30, 40) == 3);
  CHECK(s(30, 120) == 4);
  const std::uint16_t corridor = s(74, 10);
  CHECK(corridor > 4);  // a new id, above the units'
  CHECK(s(74, 80) == corridor);
  CHECK(s(74, 155) == corridor);  // one space, not one stretch per office
  CHECK(s(62, 40) != 0);          // the doorway is labelled (office or corridor)
}

TEST_CASE("segmentation: the part of a room a unit missed, open to it over more than a door, stays the unit's") {
  ClassGrid g(64, 164, kOcc);
  for (int r = 2; r <= 61; ++r)
    for (int c = 2; c <= 161; ++c) g(r, c) = kFree;
  WorldResult w;
  w.map.resolution = 0.05;
  w.units = {unit(3, 1.5, 1.5, 120.5, 61.5)};  // 2 m of the room's east end uncovered
  const cv::Mat1w s = render_segmentation(g, w);
  CHECK(s(30, 150) == 3);
  CHECK(s(5, 160) == 3);
}
