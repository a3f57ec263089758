// Every loader path: map_server YAML (trinary/scale/raw, negate, PNG and PGM images),
// bare PGM (P2, P5, 16-bit) and PNG (grey, colour, grey+alpha, 16-bit) images.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/io/map_loader.h"
#include "tests/indoor_io/temp_dir.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::TempDir;

namespace {

// A 4x3 test pattern: row 0 = occupied (0), row 1 = unknown (205), row 2 = free (254),
// with one extra twist per row in the last column.
const std::vector<std::uint8_t> kPattern = {0, 0, 0, 254,  //
                                            205, 205, 205, 0,  //
                                            254, 254, 254, 205};

std::string pgm_p5(int w, int h, const std::vector<std::uint8_t>& px, const std::string& comment = "") {
  std::string s = "P5\n";
  if (!comment.empty()) s += "# " + comment + "\n";
  s += std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  s.append(px.begin(), px.end());
  return s;
}

std::string png_bytes(const cv::Mat& img) {
  std::vector<unsigned char> buf;
  REQUIRE(cv::imencode(".png", img, buf));
  return std::string(buf.begin(), buf.end());
}

cv::Mat1b pattern_mat() {
  cv::Mat1b m(3, 4);
  for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = kPattern[static_cast<std::size_t>(i)];
  return m;
}

Cell at(const OccupancyMap& m, int r, int c) { return static_cast<Cell>(m.grid(r, c)); }

void check_pattern(const OccupancyMap& m) {
  REQUIRE(m.rows() == 3);
  REQUIRE(m.cols() == 4);
  CHECK(at(m, 0, 0) == Cell::Occupied);
  CHECK(at(m, 0, 3) == Cell::Free);
  CHECK(at(m, 1, 0) == Cell::Unknown);
  CHECK(at(m, 1, 3) == Cell::Occupied);
  CHECK(at(m, 2, 0) == Cell::Free);
  CHECK(at(m, 2, 3) == Cell::Unknown);
  const ClassCounts c = m.counts();
  CHECK(c.free == 4);
  CHECK(c.unknown == 4);
  CHECK(c.occupied == 4);
}

}  // namespace

TEST_CASE("classify_value follows map_server thresholds") {
  Thresholds t;  // 0.65 / 0.196
  CHECK(classify_value(0, t) == Cell::Occupied);
  CHECK(classify_value(89, t) == Cell::Occupied);   // p = 0.651
  CHECK(classify_value(90, t) == Cell::Unknown);    // p = 0.647
  CHECK(classify_value(205, t) == Cell::Unknown);   // p = 0.196 (not < 0.196)
  CHECK(classify_value(206, t) == Cell::Free);
  CHECK(classify_value(254, t) == Cell::Free);
  t.negate = true;
  CHECK(classify_value(0, t) == Cell::Free);
  CHECK(classify_value(255, t) == Cell::Occupied);
  t.negate = false;
  t.mode = MapMode::Raw;
  CHECK(classify_value(0, t) == Cell::Free);
  CHECK(classify_value(100, t) == Cell::Occupied);
  CHECK(classify_value(50, t) == Cell::Unknown);
  CHECK(classify_value(255, t) == Cell::Unknown);
  const Thresholds b = Thresholds::bormann();
  CHECK(classify_value(250, b) == Cell::Free);
  CHECK(classify_value(255, b) == Cell::Free);
  CHECK(classify_value(249, b) == Cell::Occupied);
  CHECK(classify_value(0, b) == Cell::Occupied);
}

TEST_CASE("map_server YAML with a P5 PGM: classes, resolution, origin, paths") {
  TempDir dir("yaml_pgm");
  dir.write("maps/m.pgm", pgm_p5(4, 3, kPattern));
  const auto yaml = dir.write("m.yaml",
                              "image: maps/m.pgm\nresolution: 0.1\norigin: [-1.5, 2.0, 0.25]\n"
                              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const OccupancyMap m = load_map_yaml(yaml);
  check_pattern(m);
  CHECK(m.resolution == Approx(0.1));
  CHECK(m.origin.x == Approx(-1.5));
  CHECK(m.origin.y == Approx(2.0));
  CHECK(m.origin.yaw == Approx(0.25));
  CHECK(m.source == yaml);
  CHECK(m.image == dir / "maps/m.pgm");
  CHECK(m.intensity(1, 0) == 205);
  CHECK(m.warnings.empty());
  // Dispatch by extension gives the same result.
  const OccupancyMap d = load_map(yaml);
  CHECK(cv::countNonZero(d.grid != m.grid) == 0);
}

TEST_CASE("map_server YAML: negate, raw and scale modes, PNG image, optional keys") {
  TempDir dir("yaml_modes");
  dir.write("m.png", png_bytes(pattern_mat()));
  SECTION("negate inverts") {
    const auto y = dir.write("n.yaml", "image: m.png\nresolution: 0.05\nnegate: 1\n");
    const OccupancyMap m = load_map_yaml(y);
    CHECK(at(m, 0, 0) == Cell::Free);
    CHECK(at(m, 2, 0) == Cell::Occupied);
    CHECK(m.thresholds.negate);
    CHECK(m.origin.x == 0.0);
  }
  SECTION("scale classifies like trinary") {
    const auto y = dir.write("s.yaml", "image: m.png\nresolution: 0.05\nmode: scale\n");
    const OccupancyMap m = load_map_yaml(y);
    check_pattern(m);
    CHECK(m.thresholds.mode == MapMode::Scale);
  }
  SECTION("raw reads occupancy percentages") {
    dir.write("r.pgm", pgm_p5(3, 3, {0, 100, 50, 255, 0, 0, 0, 0, 10}));
    const auto y = dir.write("r.yaml", "image: r.pgm\nresolution: 0.05\nmode: raw\n");
    const OccupancyMap m = load_map_yaml(y);
    CHECK(at(m, 0, 0) == Cell::Free);
    CHECK(at(m, 0, 1) == Cell::Occupied);
    CHECK(at(m, 0, 2) == Cell::Unknown);
    CHECK(at(m, 1, 0) == Cell::Unknown);
    CHECK(at(m, 2, 2) == Cell::Free);
  }
  SECTION("absolute image path and negate as bool") {
    const auto y = dir.write("a.yaml", "image: " + (dir / "m.png").string() +
                                           "\nresolution: 0.05\nnegate: false\n");
    check_pattern(load_map_yaml(y));
  }
}

TEST_CASE("bare images: P2, P5 16-bit, PNG grey/colour/alpha/16-bit") {
  TempDir dir("bare");
  SECTION("P2 ascii with comments") {
    std::string s = "P2\n# a comment\n4 3\n# another\n255\n";
    for (std::size_t i = 0; i < kPattern.size(); ++i) s += std::to_string(kPattern[i]) + (i % 4 == 3 ? "\n" : " ");
    const OccupancyMap m = load_map_image(dir.write("a.pgm", s));
    check_pattern(m);
    CHECK(m.resolution == Approx(0.05));
  }
  SECTION("P5 with 16-bit samples") {
    std::string s = "P5 4 3 65535\n";
    for (std::uint8_t v : kPattern) {
      const unsigned w = v * 257u;
      s += static_cast<char>(w >> 8);
      s += static_cast<char>(w & 0xff);
    }
    check_pattern(load_map_image(dir.write("w.pgm", s)));
  }
  SECTION("grey PNG, caller resolution and origin") {
    ImageLoadOptions o;
    o.resolution = 0.025;
    o.origin = {1.0, 2.0, 0.0};
    const OccupancyMap m = load_map_image(dir.write("g.png", png_bytes(pattern_mat())), o);
    check_pattern(m);
    CHECK(m.resolution == Approx(0.025));
    CHECK(m.origin.y == Approx(2.0));
  }
  SECTION("colour PNG is averaged over channels") {
    cv::Mat3b c;
    cv::cvtColor(pattern_mat(), c, cv::COLOR_GRAY2BGR);
    c(0, 0) = cv::Vec3b(255, 0, 0);  // average 85 -> occupied
    const OccupancyMap m = load_map_image(dir.write("c.png", png_bytes(c)));
    CHECK(m.intensity(0, 0) == 85);
    CHECK(at(m, 0, 0) == Cell::Occupied);
    CHECK(at(m, 2, 0) == Cell::Free);
  }
  SECTION("alpha channel is not averaged in") {
    cv::Mat4b c;
    cv::cvtColor(pattern_mat(), c, cv::COLOR_GRAY2BGRA);
    check_pattern(load_map_image(dir.write("a.png", png_bytes(c))));
  }
  SECTION("16-bit PNG") {
    cv::Mat1w w;
    pattern_mat().convertTo(w, CV_16U, 257.0);
    check_pattern(load_map_image(dir.write("w.png", png_bytes(w))));
  }
  SECTION("PGM map_saver comment gives the default resolution; caller conflict warns") {
    const auto p = dir.write("c.pgm", pgm_p5(4, 3, kPattern, "CREATOR: map_saver.cpp 0.100 m/pix"));
    CHECK(load_map_image(p).resolution == Approx(0.1));
    CHECK(load_map_image(p).warnings.empty());
    ImageLoadOptions o;
    o.resolution = 0.05;
    const OccupancyMap m = load_map_image(p, o);
    CHECK(m.resolution == Approx(0.05));
    REQUIRE(m.warnings.size() == 1);
    CHECK_THAT(m.warnings[0], Catch::Contains("0.1") && Catch::Contains("0.05"));
  }
  SECTION("format is sniffed from bytes, not the extension") {
    check_pattern(load_map(dir.write("really_a_pgm.png", pgm_p5(4, 3, kPattern))));
  }
}

TEST_CASE("YAML resolution conflict with the PGM header warns with both numbers") {
  TempDir dir("conflict");
  dir.write("m.pgm", pgm_p5(4, 3, kPattern, "CREATOR: map_saver.cpp 0.050 m/pix"));
  const auto y = dir.write("m.yaml", "image: m.pgm\nresolution: 0.020000\n");
  const OccupancyMap m = load_map_yaml(y);
  CHECK(m.resolution == Approx(0.02));
  REQUIRE(m.warnings.size() == 1);
  CHECK_THAT(m.warnings[0], Catch::Contains("0.02") && Catch::Contains("0.05") &&
                                Catch::Contains("m.yaml:2") && Catch::Contains("--resolution"));
  YamlLoadOptions o;
  o.resolution_override = 0.05;
  const OccupancyMap m2 = load_map_yaml(y, o);
  CHECK(m2.resolution == Approx(0.05));
  CHECK(m2.warnings.size() == 2);
  ImageLoadOptions io;
  io.resolution = 0.05;
  CHECK(load_map(y, io).resolution == Approx(0.05));
}
