// `tabletop --cloud`: the point-cloud front end feeding the table-top inference, end to end
// through the domain binary (synthetic cloud; the HOPE cloud when ../shared is there).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "synthetic_cloud.h"
#include "tests/support/shared_data.h"
#include "tests/support/tabletop_run.h"

namespace fs = std::filesystem;
namespace tp = ksmc::tests::perception;

using ksmc::tests::read_json;
using ksmc::tests::run_tabletop;

TEST_CASE("tabletop --cloud: two boxes on a table, in millimetres", "[perception][cli]") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_perception_cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  tp::pc::Points pts;
  tp::add_table(pts, 0.4, 0.3, 0.01);
  tp::add_box(pts, -0.15, 0.05, 0.3, Eigen::Vector3d(0.12, 0.06, 0.2), 0.005);
  tp::add_box(pts, 0.12, -0.08, 1.1, Eigen::Vector3d(0.08, 0.08, 0.05), 0.005);
  tp::pc::Points mm;
  for (const auto& p : tp::to_sensor(pts, tp::example_sensor_pose())) mm.push_back(1000.0 * p);
  tp::pc::save_ply(dir / "frame.ply", mm);

  REQUIRE(run_tabletop("--cloud " + (dir / "frame.ply").string() + " --cloud-units mm --out " + (dir / "out").string() +
                           " --iterations 200",
                       dir / "log.txt") == 0);
  const auto scene = read_json(dir / "out" / "scene.json");
  CHECK(scene["objects"].size() == 2);
  const auto graph = read_json(dir / "out" / "scene_graph.json");
  REQUIRE(graph["objects"].size() == 2);
  for (const auto& o : graph["objects"]) {
    CHECK(o["stable"] == true);
    CHECK(o["false"] == false);
    CHECK(o["hidden"] == false);
  }
  CHECK(graph["support"].size() == 2);  // both on the table
  for (const auto& s : graph["support"]) CHECK(s[1] == "table");

  // Bad input: a cloud with no plane exits 1 naming the file; a positional input next to --cloud exits 2.
  tp::pc::Points cube;  // uniform in a 1 m cube
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) cube.emplace_back(u(rng), u(rng), u(rng));
  tp::pc::save_ply(dir / "cube.ply", cube);
  CHECK(run_tabletop("--cloud " + (dir / "cube.ply").string() + " --out " + (dir / "bad").string(), dir / "bad.txt") !=
        0);
  std::ifstream err(dir / "bad.txt");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  CHECK(text.find((dir / "cube.ply").string() + ": no table plane") != std::string::npos);
  CHECK(run_tabletop("x.json --cloud " + (dir / "frame.ply").string() + " --out " + (dir / "bad2").string(),
                     dir / "bad2.txt") != 0);
}

TEST_CASE("tabletop --cloud on the HOPE cloud: every box on the table, none false or hidden", "[perception][cli][hope]") {
  const char* cloud = "data/tabletop/hope_video_frame/point_cloud.ply";
  if (!ksmc::tests::have_shared(cloud)) return;
  const fs::path dir = fs::temp_directory_path() / "ksmc_perception_cli_hope";
  fs::remove_all(dir);
  REQUIRE(run_tabletop("--cloud " + (ksmc::tests::shared_dir() / cloud).string() + " --cloud-units cm --out " +
                           dir.string() + " --iterations 300",
                       fs::temp_directory_path() / "ksmc_perception_cli_hope.txt") == 0);
  const auto graph = read_json(dir / "scene_graph.json");
  CHECK(graph["objects"].size() == 9);
  for (const auto& o : graph["objects"]) {
    INFO(o["id"]);
    CHECK(o["stable"] == true);
    CHECK(o["false"] == false);
    CHECK(o["hidden"] == false);
  }
  CHECK(graph["support"].size() == 9);
}
