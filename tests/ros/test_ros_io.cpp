// ros/io: OccupancyGrid <-> PGM + YAML (rows flipped, trinary values, origin kept), the
// last /map of a bag written here, PointCloud2 -> PCD (NaN points skipped).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <catch2/catch.hpp>

#include "ros/io/bag_map.h"
#include "ros/io/cloud_files.h"
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

TEST_CASE("a PointCloud2 becomes a binary PCD of its finite x y z", "[ros][cloud]") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto cloud = ri::xyz_cloud({{1.0F, 2.0F, 3.0F}, {nan, 0.0F, 0.0F}, {-0.5F, 0.25F, 4.0F}, {0.0F, 0.0F, nan}}, "cam");
  CHECK(cloud.header.frame_id == "cam");
  CHECK_FALSE(cloud.is_dense);
  // As an organized 2 x 2 cloud with padded rows: row order kept, NaN points skipped.
  cloud.height = 2;
  cloud.width = 2;
  cloud.row_step = 40;
  std::vector<std::uint8_t> padded(80, 0);
  for (int row = 0; row < 2; ++row)
    std::copy_n(cloud.data.begin() + row * 32, 32, padded.begin() + row * 40);
  cloud.data = padded;
  const auto points = ri::cloud_points(cloud);
  REQUIRE(points.size() == 2);
  CHECK(points[1] == std::array<float, 3>{-0.5F, 0.25F, 4.0F});

  const fs::path pcd = fs::temp_directory_path() / "ksmc_test_ros_io.pcd";
  ri::write_pcd(pcd, points);
  std::ifstream in(pcd, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto data = text.find("DATA binary\n");
  REQUIRE(data != std::string::npos);
  CHECK(text.find("FIELDS x y z\n") != std::string::npos);
  CHECK(text.find("POINTS 2\n") != std::string::npos);
  REQUIRE(text.size() == data + 12 + 24);
  float first[3];
  std::memcpy(first, text.data() + data + 12, sizeof first);
  CHECK((first[0] == 1.0F && first[1] == 2.0F && first[2] == 3.0F));
  fs::remove(pcd);
  CHECK_THROWS_WITH(ri::write_pcd(pcd, {}), Catch::Contains("ksmc_test_ros_io.pcd: no finite point"));
}

TEST_CASE("cloud_points rejects clouds without float x y z or with short data", "[ros][cloud]") {
  auto cloud = ri::xyz_cloud({{1.0F, 2.0F, 3.0F}}, "cam");
  auto no_z = cloud;
  no_z.fields.pop_back();
  CHECK_THROWS_WITH(ri::cloud_points(no_z), Catch::Contains("no field 'z' (fields: x, y)"));
  auto as_double = cloud;
  as_double.fields[0].datatype = sensor_msgs::PointField::FLOAT64;
  CHECK_THROWS_WITH(ri::cloud_points(as_double), Catch::Contains("field 'x' is not FLOAT32"));
  auto shorter = cloud;
  shorter.data.resize(8);
  CHECK_THROWS_WITH(ri::cloud_points(shorter), Catch::Contains("data holds 8 bytes"));
  auto big = cloud;
  big.is_bigendian = true;
  CHECK_THROWS_WITH(ri::cloud_points(big), Catch::Contains("big-endian"));
}
