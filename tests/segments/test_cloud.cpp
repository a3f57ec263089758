#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "stdlib/segments/cloud.h"

using namespace ksmc::stdlib::segments;

namespace {
std::string error_of(const std::string& text) {
  try {
    parse_points(text, "c.txt");
  } catch (const CloudError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("point clouds parse x y lines with comments", "[segments][cloud]") {
  const auto pts = parse_points("# header\n1 2\n  -0.5\t3e-1   # trailing\n\n+4,5\r\n", "c.txt");
  REQUIRE(pts.size() == 3);
  CHECK(pts[0] == Vec2{1, 2});
  CHECK(pts[1] == Vec2{-0.5, 0.3});
  CHECK(pts[2] == Vec2{4, 5});
}

TEST_CASE("bad point clouds name the file and line", "[segments][cloud]") {
  CHECK(error_of("1 2\n3\n") == "c.txt:2: error: expected two numbers 'x y' (metres), got '3'");
  CHECK(error_of("1 2 3\n") == "c.txt:1: error: expected two numbers 'x y' (metres), got '1 2 3'");
  CHECK(error_of("1 2\n\n1 x\n") == "c.txt:3: error: 'x' is not a number");
  CHECK(error_of("nan 1\n") == "c.txt:1: error: coordinates must be finite (no nan or inf)");
  CHECK(error_of("1 inf\n") == "c.txt:1: error: coordinates must be finite (no nan or inf)");
  CHECK(error_of("0 0\n1e7 1\n") == "c.txt:2: error: coordinates must be within +-1e6 m");
  CHECK(error_of("1e999 1\n") == "c.txt:1: error: '1e999' is not a number");
  CHECK(error_of("# nothing\n\n") == "c.txt: error: the point cloud is empty (no 'x y' line)");
  CHECK(error_of("") == "c.txt: error: the point cloud is empty (no 'x y' line)");
  CHECK(error_of(std::string("1 2\n3 \0 4\n", 10)).find("c.txt:2: error:") == 0);
}

TEST_CASE("load_points reports a missing file", "[segments][cloud]") {
  const auto p = std::filesystem::temp_directory_path() / "ksmc_segments_no_such_cloud.txt";
  std::filesystem::remove(p);
  CHECK_THROWS_WITH(load_points(p), Catch::Contains("cannot open"));
  {
    std::ofstream(p) << "0 0\n1 1\n";
  }
  CHECK(load_points(p).size() == 2);
  std::filesystem::remove(p);
}
