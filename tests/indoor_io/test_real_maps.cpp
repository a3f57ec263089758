// The real maps of ../shared: every Bormann/IPA test map loads with both the benchmark convention
// (>= 250 free) and map_server thresholds, and the two agree; ubremen-cartesium's YAML/PGM
// resolution conflict is reported. Skips cleanly when ../shared is absent.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "stdlib/indoor/io/map_loader.h"
#include "tests/support/shared_data.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::io;
namespace fs = std::filesystem;

TEST_CASE("all Bormann/IPA test maps load and classify sensibly both ways") {
  const std::string rel = "data/maps/bormann_ipa/test_maps";
  if (!ksmc::tests::have_shared(rel)) return;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(ksmc::tests::shared_dir() / rel)) {
    const auto ext = e.path().extension().string();
    if (ext == ".png" || ext == ".pgm") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 100);
  std::printf("%-45s %10s %9s %9s %9s | %9s %9s %9s  agree\n", "map", "size", "free", "unknown",
              "occupied", "ms-free", "ms-unkn", "ms-occ");
  for (const auto& f : files) {
    INFO(f.string());
    ImageLoadOptions bormann;
    bormann.thresholds = Thresholds::bormann();
    const OccupancyMap b = load_map_image(f, bormann);
    const OccupancyMap s = load_map_image(f);  // map_server 0.65 / 0.196
    const ClassCounts cb = b.counts(), cs = s.counts();
    const double n = static_cast<double>(cb.total());
    // Free under the benchmark convention (v >= 250) implies free under map_server (v >= 206).
    const cv::Mat bf = b.grid == static_cast<std::uint8_t>(Cell::Free);
    const cv::Mat sf = s.grid == static_cast<std::uint8_t>(Cell::Free);
    const double agree = 1.0 - cv::countNonZero(bf != sf) / n;
    std::printf("%-45s %4dx%-5d %9zu %9zu %9zu | %9zu %9zu %9zu  %.4f\n",
                f.filename().string().c_str(), b.cols(), b.rows(), cb.free, cb.unknown,
                cb.occupied, cs.free, cs.unknown, cs.occupied, agree);
    CHECK(b.resolution == Approx(0.05));
    CHECK(cb.unknown == 0);
    CHECK(cv::countNonZero(bf & ~sf) == 0);
    // Sensible: free space is a real share of the map, and both conventions mostly agree on it.
    CHECK(cb.free / n > 0.02);
    CHECK(cb.free / n < 0.98);
    CHECK(cs.free >= cb.free);
    // Two real SLAM maps paint unexplored space light grey (230): p = 0.098 < 0.196, so map_server's
    // default thresholds call it free. A stricter free_thresh (0.05, i.e. v > 242) fixes them.
    const std::string name = f.filename().string();
    if (name == "lab_b.png" || name == "intel_map.png") {
      CHECK(agree < 0.9);
      ImageLoadOptions strict;
      strict.thresholds.free_thresh = 0.05;
      const OccupancyMap s2 = load_map_image(f, strict);
      const cv::Mat sf2 = s2.grid == static_cast<std::uint8_t>(Cell::Free);
      const double agree2 = 1.0 - cv::countNonZero(bf != sf2) / n;
      std::printf("%-45s with free_thresh 0.05: agree %.4f\n", name.c_str(), agree2);
      CHECK(agree2 > 0.9);
    } else {
      CHECK(agree > 0.9);
    }
  }
}

TEST_CASE("ubremen-cartesium: YAML says 0.02, PGM header 0.05 -> warning, YAML wins") {
  const std::string rel = "data/maps/rose2_ros/carmen/ubremen-cartesium.yaml";
  if (!ksmc::tests::have_shared(rel)) return;
  const fs::path y = ksmc::tests::shared_dir() / rel;
  const OccupancyMap m = load_map_yaml(y);
  CHECK(m.cols() == 1472);
  CHECK(m.rows() == 864);
  CHECK(m.resolution == Approx(0.02));
  CHECK(m.origin.x == Approx(-5.0));
  CHECK(m.origin.y == Approx(-16.52));
  REQUIRE(m.warnings.size() == 1);
  std::printf("%s\n", m.warnings[0].c_str());
  CHECK_THAT(m.warnings[0], Catch::Contains("0.02") && Catch::Contains("0.05"));
  const ClassCounts c = m.counts();
  std::printf("ubremen-cartesium: free %zu unknown %zu occupied %zu\n", c.free, c.unknown,
              c.occupied);
  CHECK(c.free > 150000);  // the README measures about 200k free cells
  CHECK(c.free < 250000);
  CHECK(c.occupied > 0);
  CHECK(c.unknown > c.free);  // most of the rectangle is unexplored outside area
  YamlLoadOptions o;
  o.resolution_override = 0.05;
  CHECK(load_map_yaml(y, o).resolution == Approx(0.05));
}
