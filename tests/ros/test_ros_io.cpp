// ros/io: OccupancyGrid <-> PGM + YAML (rows flipped, trinary values, origin kept) and
// the last /map of a bag written here.
#include <filesystem>

#include <catch2/catch.hpp>

#include "ros/io/bag_map.h"
#include "ros/io/grid_files.h"

namespace ri = ksmc::ros_io;
namespace fs = std::filesystem;

namespace {

nav_msgs::OccupancyGrid small_grid(std::int8_t corner) {
  nav_msgs::OccupancyGrid g;
  g.header.frame_id = "map";
  g.info.width = 3;
  g.info.height = 2;
  g.info.resolution = 0.1F;
  g.info.origin.position.x = -1.5;
  g.info.origin.position.y = 2.0;
  g.info.origin.orientation.w = 1.0;
  g.data = {corner, 0, -1,   // bottom row (y = origin)
            100, 50, 10};    // top row
  return g;
}

}  // namespace

TEST_CASE("a grid written as PGM + YAML reads back trinary, same geometry", "[ros]") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_test_ros_io_grid";
  fs::remove_all(dir);
  const auto yaml = ri::write_map_files(small_grid(100), dir, "map");
  CHECK(yaml == dir / "map.yaml");
  const auto back = ri::read_map_files(yaml);
  CHECK(back.info.width == 3);
  CHECK(back.info.height == 2);
  CHECK(back.info.resolution == Approx(0.1));
  CHECK(back.info.origin.position.x == Approx(-1.5));
  CHECK(back.info.origin.position.y == Approx(2.0));
  // 100 -> occupied, 0 -> free, -1 -> unknown, 50 -> unknown (between the thresholds), 10 -> free
  CHECK(back.data == std::vector<std::int8_t>{100, 0, -1, 100, -1, 0});
  fs::remove_all(dir);
}

TEST_CASE("write_map_files rejects a grid whose data does not match its size", "[ros]") {
  auto g = small_grid(0);
  g.data.pop_back();
  CHECK_THROWS_WITH(ri::write_map_files(g, fs::temp_directory_path(), "bad"), Catch::Contains("5 cells for 3x2"));
}

TEST_CASE("the last /map of a bag is read back", "[ros]") {
  const fs::path bag = fs::temp_directory_path() / "ksmc_test_ros_io.bag";
  ri::write_map_bag(bag, {small_grid(0), small_grid(100), small_grid(-1)});
  const auto last = ri::read_last_map(bag);
  CHECK(last.data.front() == -1);
  CHECK(last.info.width == 3);
  CHECK_THROWS_WITH(ri::read_last_map(bag, "/other"), Catch::Contains("no nav_msgs/OccupancyGrid on /other"));
  CHECK_THROWS_WITH(ri::read_last_map(fs::temp_directory_path() / "ksmc_missing.bag"), Catch::Contains("ksmc_missing.bag"));
  fs::remove(bag);
}
