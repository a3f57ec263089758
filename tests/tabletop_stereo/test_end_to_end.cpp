// End to end: the same generated scene (a stack, an object on an invisible supporter, a
// printed product picture) through stereo -> tabletop and through cloud -> tabletop, both
// via the domain binary; the scene-graph decisions are checked (e2e_scene.h says why each
// arises).
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "e2e_scene.h"
#include "stdlib/tabletop/perception/cloud_io.h"
#include "tools/tabletop_sim/depth_render.h"
#include "stereo_scenes.h"
#include "tests/support/tabletop_run.h"

namespace fs = std::filesystem;
namespace ts = ksmc::tests::stereo;
namespace sim = ksmc::tools::tabletop_sim;
namespace pc = ksmc::stdlib::tabletop::perception;
using ksmc::tests::read_json;
using ksmc::tests::run_tabletop;

namespace {

struct Decision {
  bool stable = false, is_false = false, hidden = false;
  std::string supporter;  // "" when none
};

std::map<std::string, Decision> decisions(const nlohmann::json& graph) {
  std::map<std::string, Decision> out;
  for (const auto& o : graph["objects"])
    out[o["id"].get<std::string>()] = {o["stable"].get<bool>(), o["false"].get<bool>(), o["hidden"].get<bool>(), ""};
  for (const auto& s : graph["support"]) out[s[0].get<std::string>()].supporter = s[1].get<std::string>();
  return out;
}

void print(const std::string& what, const std::map<std::string, Decision>& d) {
  for (const auto& [id, x] : d)
    std::printf("%s %-8s stable %d false %d hidden %d on %s\n", what.c_str(), id.c_str(), x.stable, x.is_false, x.hidden,
                x.supporter.c_str());
}

sim::Pose to_sim(const ksmc::stdlib::tabletop::Pose& p) {
  sim::Pose s;
  s.t = p.t;
  s.q = p.q;
  return s;
}

}  // namespace

TEST_CASE("end to end: stereo -> scene graph (stack, hidden supporter, printed picture)", "[stereo][e2e]") {
  const ts::E2eScene scene = ts::e2e_scene();
  const ts::sy::Rig rig = ts::standard_rig();
  const fs::path dir = ts::fresh_dir("e2e_stereo");
  const auto pair = ts::sy::render_pair(rig, scene.present, 7);
  cv::imwrite((dir / "left.png").string(), pair.left);
  cv::imwrite((dir / "right.png").string(), pair.right);
  auto calib = ts::sy::rig_calib(rig);
  ts::st::save_calib(dir / "stereo.yaml", calib);
  calib.table_in_left.reset();  // second run: the table fitted to the stereo points
  ts::st::save_calib(dir / "no_table.yaml", calib);
  for (const auto& b : scene.database) ts::sy::write_object_folder(dir / "db", b);

  for (const std::string yaml : {"stereo.yaml", "no_table.yaml"}) {
    INFO(yaml);
    const fs::path out = dir / ("out_" + yaml);
    REQUIRE(run_tabletop("--stereo " + (dir / "left.png").string() + " " + (dir / "right.png").string() + " --calib " +
                             (dir / yaml).string() + " --db " + (dir / "db").string() + " --out " + out.string() +
                             " --iterations 400 --seed 3",
                         dir / "log.txt") == 0);
    const auto written = read_json(out / "scene.json");
    for (const auto& o : written["objects"]) CHECK(o["keypoints"]["model"].size() >= 6);
    const auto d = decisions(read_json(out / "scene_graph.json"));
    print("stereo " + yaml, d);
    REQUIRE(d.size() == 5);  // crate base top lid poster; black is not detected
    REQUIRE(d.count("black") == 0);
    CHECK(d.at("crate").supporter == "table");
    CHECK(d.at("base").supporter == "table");
    CHECK(d.at("top").supporter == "base");
    for (const char* id : {"crate", "base", "top"}) {
      CHECK_FALSE(d.at(id).is_false);
      CHECK_FALSE(d.at(id).hidden);
    }
    CHECK(d.at("lid").hidden);
    CHECK_FALSE(d.at("lid").is_false);
    CHECK(d.at("poster").is_false);
  }
}

TEST_CASE("end to end: cloud -> scene graph (stack, absorbing supporter, multipath ghost)", "[stereo][e2e][cloud]") {
  const ts::E2eScene scene = ts::e2e_scene();
  const ts::sy::Rig rig = ts::standard_rig();
  const fs::path dir = ts::fresh_dir("e2e_cloud");
  std::vector<sim::Box> boxes;
  for (const auto& b : scene.present) boxes.push_back({b.size, to_sim(b.pose)});
  sim::Camera cam;
  sim::Rng rng(9);
  sim::TableSpec table;
  const sim::Pose table_from_camera = to_sim(rig.table_from_left);
  const auto cloud_cam = sim::render_depth(rng, cam, table_from_camera, boxes, table, sim::DepthParams{});
  // Physical effects: the black box returns nothing; the glossy picture's returns are 3 cm long.
  const auto& black = boxes[static_cast<std::size_t>(scene.black)];
  const auto& crate = boxes[static_cast<std::size_t>(scene.crate)];
  pc::Points cloud;
  int ghost = 0;
  for (const Eigen::Vector3d& p : cloud_cam) {
    const Eigen::Vector3d t = table_from_camera.apply(p);
    const Eigen::Vector3d in_black = black.pose.inverse().apply(t);
    if ((in_black.cwiseAbs() - 0.5 * black.size).maxCoeff() > -0.004 &&
        ((in_black.cwiseAbs() - 0.5 * black.size).array() < 0.004).all())
      continue;  // on the black box's surface
    const Eigen::Vector3d in_crate = crate.pose.inverse().apply(t);
    if (std::abs(in_crate.y() - scene.picture_min.y()) < 0.004 && in_crate.x() > scene.picture_min.x() &&
        in_crate.x() < scene.picture_max.x() && in_crate.z() > scene.picture_min.z() && in_crate.z() < scene.picture_max.z()) {
      cloud.push_back(p + 0.03 * p.normalized());
      ++ghost;
      continue;
    }
    cloud.push_back(p);
  }
  CHECK(ghost > 100);
  pc::save_ply(dir / "frame.ply", cloud);
  REQUIRE(run_tabletop("--cloud " + (dir / "frame.ply").string() + " --out " + (dir / "out").string() +
                           " --iterations 400 --seed 3",
                       dir / "log.txt") == 0);
  const auto written = read_json(dir / "out" / "scene.json");
  const auto d = decisions(read_json(dir / "out" / "scene_graph.json"));
  // Name the cloud's boxes after the nearest true box (camera frame), the ghost after none.
  const sim::Pose camera_from_table = table_from_camera.inverse();
  std::map<std::string, std::string> name;
  for (const auto& o : written["objects"]) {
    const Eigen::Vector3d c(o["pose"]["t"][0], o["pose"]["t"][1], o["pose"]["t"][2]);
    std::string best = "?";
    double best_d = 0.03;
    for (const auto& b : scene.present) {
      const double dist = (camera_from_table.apply(b.pose.t) - c).norm();
      if (dist < best_d) best_d = dist, best = b.name;
    }
    const Eigen::Vector3d in_crate = crate.pose.inverse().apply(table_from_camera.apply(c));
    if (best == "?" && (in_crate.cwiseAbs() - 0.5 * crate.size).maxCoeff() < 0.0) best = "ghost";
    name[o["id"].get<std::string>()] = best;
  }
  std::map<std::string, Decision> named;
  for (const auto& [id, x] : d) {
    Decision y = x;
    if (name.count(y.supporter)) y.supporter = name[y.supporter];
    named[name.count(id) ? name[id] : id] = y;
  }
  print("cloud", named);
  REQUIRE(named.size() == 5);  // crate base top lid ghost; black has no returns
  CHECK(named.count("black") == 0);
  CHECK(named.at("crate").supporter == "table");
  CHECK(named.at("base").supporter == "table");
  CHECK(named.at("top").supporter == "base");
  for (const char* id : {"crate", "base", "top"}) {
    CHECK_FALSE(named.at(id).is_false);
    CHECK_FALSE(named.at(id).hidden);
  }
  CHECK(named.at("lid").hidden);
  CHECK_FALSE(named.at("lid").is_false);
  CHECK(named.at("ghost").is_false);
}
