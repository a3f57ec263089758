// The `--bag FILE.bag` path, as the indoor kit's hook takes it (ros/io/bag_files.h, C++20
// side): the bundled map goes into a bag, the last /map comes back out as PGM + YAML, and
// the indoor domain run in-process on it gives the same units as on the original files.
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "ros/io/bag_files.h"
#include "ros/src/domain_run.h"

namespace fs = std::filesystem;
namespace rn = ksmc::ros_nodes;

namespace {

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  REQUIRE(in);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("a map read back from a bag runs like the original map files", "[ros]") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_test_bag_hook";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path yaml = fs::path(KSMC_SOURCE_DIR) / "examples/indoor/sim_office.yaml";
  ksmc::ros_io::map_files_to_bag(yaml, dir / "map.bag");
  const fs::path extracted = ksmc::ros_io::extract_last_map(dir / "map.bag", dir / "bag_map");
  CHECK(extracted == dir / "bag_map" / "map.yaml");

  rn::RunSettings s;
  s.iterations = 3000;
  const rn::RunOutcome from_bag = rn::run_indoor(extracted, dir / "from_bag", s);
  const rn::RunOutcome from_files = rn::run_indoor(yaml, dir / "from_files", s);
  INFO(from_bag.messages << from_files.messages);
  REQUIRE(from_bag.exit_code == 0);
  {
    rn::RunSettings until_plateau;  // iterations 0: --iterations auto
    until_plateau.iterations = 0;
    const rn::RunOutcome r = rn::run_indoor(yaml, dir / "until_plateau", until_plateau);
    INFO(r.messages);
    REQUIRE(r.exit_code == 0);
    const auto summary = read_json(dir / "until_plateau" / "summary.json");
    CHECK(summary.at("until_plateau").at("chains_reached") == 1);
  }
  REQUIRE(from_files.exit_code == 0);
  const auto a = read_json(dir / "from_bag" / "world.json");
  const auto b = read_json(dir / "from_files" / "world.json");
  CHECK(a["map"]["width"] == 600);
  CHECK(a["map"]["height"] == 400);
  CHECK(a["map"]["cells"] == b["map"]["cells"]);  // same free / unknown / occupied counts
  CHECK(a["units"] == b["units"]);                // same seed, same map: same result
  CHECK(a["doors"] == b["doors"]);
  CHECK(fs::exists(dir / "from_bag" / "report.html"));
  fs::remove_all(dir);
}

TEST_CASE("extract_last_map names the bag it cannot read", "[ros]") {
  const fs::path missing = fs::temp_directory_path() / "ksmc_no_such.bag";
  CHECK_THROWS_WITH(ksmc::ros_io::extract_last_map(missing, fs::temp_directory_path() / "ksmc_no_map"),
                    Catch::Contains("ksmc_no_such.bag"));
}
