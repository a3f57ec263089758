// The point-cloud front end end to end on synthetic clouds: table frame, clusters, boxes,
// scene.json read back by stdlib/tabletop/scene_io; units; bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/scene_json.h"
#include "stdlib/tabletop/scene_io.h"
#include "synthetic_cloud.h"

using namespace ksmc::stdlib::tabletop::perception;
namespace tp = ksmc::tests::perception;
namespace fs = std::filesystem;

namespace {

// Two boxes on a table, the boxes sampled on a grid of `step` m.
Points two_box_scene(double step = 0.005) {
  Points pts;
  tp::add_table(pts, 0.4, 0.3, std::max(step, 0.01));
  tp::add_box(pts, -0.15, 0.05, 0.3, Eigen::Vector3d(0.12, 0.06, 0.2), step);
  tp::add_box(pts, 0.12, -0.08, 1.1, Eigen::Vector3d(0.08, 0.08, 0.05), step);
  return tp::to_sensor(pts, tp::example_sensor_pose());
}

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("ksmc_perception_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string error_of(const fs::path& file, Units units = Units::m) {
  try {
    CloudOptions options;
    options.units = units;
    (void)scene_from_cloud(file, options);
  } catch (const CloudError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("front end: table frame, two boxes, scene.json round trip", "[perception][front_end]") {
  const CloudScene cs = scene_from_points(two_box_scene(), "synthetic");
  REQUIRE(cs.scene.objects.size() == 2);
  // The table normal in the sensor frame is the sensor pose's z axis.
  const Eigen::Vector3d n = tp::example_sensor_pose().linear().col(2);
  CHECK(cs.table.table_in_cloud.rotation().col(2).dot(n) == Approx(1.0).margin(1e-6));
  CHECK(cs.table.extent.maxCoeff() == Approx(0.8).margin(0.02));
  // Clusters are ordered by table-frame x; sizes modulo the footprint's axis order.
  const auto sorted = [](Eigen::Vector3d s) {
    if (s.x() > s.y()) std::swap(s.x(), s.y());
    return s;
  };
  const Eigen::Vector3d tall = sorted(cs.scene.objects[0].size), flat = sorted(cs.scene.objects[1].size);
  const bool first_is_tall = tall.z() > flat.z();
  const Eigen::Vector3d a = first_is_tall ? tall : flat, b = first_is_tall ? flat : tall;
  CHECK(a.x() == Approx(0.06).margin(0.004));
  CHECK(a.y() == Approx(0.12).margin(0.004));
  CHECK(a.z() == Approx(0.2).margin(0.004));
  CHECK(b.x() == Approx(0.08).margin(0.004));
  CHECK(b.z() == Approx(0.05).margin(0.004));
  CHECK(cs.object_points[0].size() > 100);

  const fs::path dir = temp_dir("roundtrip");
  write_scene_json(dir / "scene.json", cs.scene);
  const auto load = ksmc::stdlib::tabletop::load_scene(dir / "scene.json");
  CHECK(load.warnings.empty());
  REQUIRE(load.scene.objects.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK((load.scene.objects[i].pose.t - cs.scene.objects[i].pose.t).norm() < 1e-5);
    CHECK((load.scene.objects[i].size - cs.scene.objects[i].size).norm() < 1e-5);
    CHECK(load.scene.objects[i].obb().min_z() == Approx(0.0).margin(1e-5));  // standing on the table
  }
  // Byte-identical output for identical input.
  CHECK(scene_json_text(cs.scene) == scene_json_text(scene_from_points(two_box_scene(), "synthetic").scene));
}

TEST_CASE("front end: the table plane's RMS is the scene's depth noise, written and read back", "[perception][front_end]") {
  // A noise-free cloud: under 1 mm (the plane's least-squares refit leans a little toward the
  // boxes' feet in the inlier band), which keeps the tolerance at its 5 mm floor.
  CHECK(scene_from_points(two_box_scene(), "synthetic").scene.depth_noise < 0.001);
  // The same boxes on a table whose points carry 2 mm of depth noise.
  Points pts;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.002);
  Points table;
  tp::add_table(table, 0.4, 0.3, 0.005);
  for (Eigen::Vector3d p : table) pts.push_back(p + Eigen::Vector3d(0, 0, noise(rng)));
  tp::add_box(pts, -0.15, 0.05, 0.3, Eigen::Vector3d(0.12, 0.06, 0.2), 0.005);
  tp::add_box(pts, 0.12, -0.08, 1.1, Eigen::Vector3d(0.08, 0.08, 0.05), 0.005);
  const CloudScene cs = scene_from_points(tp::to_sensor(pts, tp::example_sensor_pose()), "noisy");
  CHECK(cs.scene.depth_noise == Approx(0.002).margin(0.0002));
  CHECK(cs.scene.depth_noise == Approx(cs.table.noise).margin(0.5e-6));  // to the micrometre
  const fs::path dir = temp_dir("depth_noise");
  write_scene_json(dir / "scene.json", cs.scene);
  CHECK(ksmc::stdlib::tabletop::load_scene(dir / "scene.json").scene.depth_noise == cs.scene.depth_noise);
}

TEST_CASE("front end: the floor beside the table does not turn the table upside down", "[perception][front_end]") {
  // A 0.8 x 0.6 m table, a 10 cm box on it, and around the table a floor 30 cm below (the
  // floor the camera sees past the table's far edge, as in PCL's table_scene_mug_stereo_textured):
  // more floor points lie within side_band below the plane than box points above it. Over
  // the table's own rectangle only the box counts, and the box is above.
  Points pts;
  tp::add_table(pts, 0.4, 0.3, 0.005);
  tp::add_box(pts, 0.05, -0.02, 0.4, Eigen::Vector3d(0.1, 0.1, 0.1), 0.004);
  const std::size_t on_table = pts.size();
  for (double x = -0.7; x <= 0.7; x += 0.008)
    for (double y = -0.6; y <= 0.6; y += 0.008)
      if (std::abs(x) > 0.42 || std::abs(y) > 0.32) pts.emplace_back(x, y, -0.3);
  REQUIRE(pts.size() - on_table > 2 * 4000);  // the floor's points outnumber the box's
  const CloudScene cs = scene_from_points(tp::to_sensor(pts, tp::example_sensor_pose()), "floor");
  const Eigen::Vector3d n = tp::example_sensor_pose().linear().col(2);
  CHECK(cs.table.table_in_cloud.rotation().col(2).dot(n) == Approx(1.0).margin(1e-6));
  REQUIRE(cs.scene.objects.size() == 1);
  CHECK(cs.scene.objects[0].size.z() == Approx(0.1).margin(0.004));
}

TEST_CASE("front end: a sparse cloud gets its clustering tolerance from its point spacing", "[perception][front_end]") {
  // A 14 mm grid (a low-resolution sensor, a far table, a voxel filter): no point has a
  // neighbour within the 8 mm floor.
  const Points sparse = two_box_scene(0.014);
  const CloudScene cs = scene_from_points(sparse, "sparse");
  CHECK(cs.point_spacing == Approx(0.014).margin(0.001));
  CHECK(cs.cluster_tolerance == Approx(0.028).margin(0.002));
  REQUIRE(cs.scene.objects.size() == 2);
  for (const auto& o : cs.scene.objects) {
    const double high = o.size.z(), wide = std::max(o.size.x(), o.size.y());
    const bool tall = high > 0.1;
    CHECK(high == Approx(tall ? 0.2 : 0.05).margin(0.015));
    CHECK(wide == Approx(tall ? 0.12 : 0.08).margin(0.015));
  }
  // The fixed tolerance finds no object in it.
  CloudOptions fixed;
  fixed.clusters.spacing_factor = 0.0;
  CHECK_THROWS_AS(scene_from_points(sparse, "sparse", fixed), CloudError);
  // A dense cloud (3 mm grid) keeps the floor.
  CHECK(scene_from_points(two_box_scene(0.003), "dense").cluster_tolerance == Approx(0.008));
}

TEST_CASE("front end: PLY units and bad input name the file", "[perception][front_end][errors]") {
  const fs::path dir = temp_dir("errors");
  Points cm;
  for (const auto& p : two_box_scene()) cm.push_back(100.0 * p);
  save_ply(dir / "cm.ply", cm);
  CloudOptions options;
  options.units = Units::cm;
  const CloudScene cs = scene_from_cloud(dir / "cm.ply", options);
  CHECK(cs.scene.objects.size() == 2);
  CHECK(parse_units("mm") == Units::mm);
  CHECK_THROWS_AS(parse_units("inch"), std::invalid_argument);

  std::ofstream(dir / "empty.ply") << "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                      "property float z\nend_header\n";
  const std::string empty = error_of(dir / "empty.ply");
  CHECK(empty.rfind((dir / "empty.ply").string(), 0) == 0);

  Points nan = two_box_scene();
  nan[7].y() = std::numeric_limits<double>::quiet_NaN();
  save_ply(dir / "nan.ply", nan);
  const std::string bad = error_of(dir / "nan.ply");
  INFO(bad);
  CHECK(bad.rfind((dir / "nan.ply").string(), 0) == 0);
  CHECK(bad.find("point 7") != std::string::npos);

  Points cube;  // uniform in a 1 m cube: no plane holds 15 % of it
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) cube.emplace_back(u(rng), u(rng), u(rng));
  save_ply(dir / "cube.ply", cube);
  const std::string noplane = error_of(dir / "cube.ply");
  INFO(noplane);
  CHECK(noplane.rfind((dir / "cube.ply").string(), 0) == 0);
  CHECK(noplane.find("no table plane") != std::string::npos);

  Points bare;
  tp::add_table(bare, 0.4, 0.3, 0.01);
  save_ply(dir / "bare.ply", bare);
  CHECK(error_of(dir / "bare.ply").find("no object above the table") != std::string::npos);
  CHECK(error_of(dir / "missing.ply").find("cannot open file") != std::string::npos);
  std::ofstream(dir / "cloud.xyz") << "1 2 3\n";
  CHECK(error_of(dir / "cloud.xyz").find("unknown cloud format") != std::string::npos);

#ifdef KSMC_CLOUD_SCENE_EXE
  // The driver exits non-zero with the file's name on stderr.
  const std::string cmd = std::string(KSMC_CLOUD_SCENE_EXE) + " " + (dir / "nan.ply").string() + " --out " +
                          (dir / "out").string() + " 2> " + (dir / "stderr.txt").string();
  CHECK(std::system(cmd.c_str()) != 0);
  std::ifstream err(dir / "stderr.txt");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  CHECK(text.find("nan.ply: point 7") != std::string::npos);
#endif
}
