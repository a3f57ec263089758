// scene.json validation: every error names the file and the JSON path.
#include <catch2/catch.hpp>

#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "stdlib/tabletop/scene_io.h"

using namespace ksmc::stdlib::tabletop;
using nlohmann::json;

namespace {

json valid_doc() {
  return json::parse(R"({
    "camera": {"fx": 615.0, "fy": 615.0, "cx": 320.0, "cy": 240.0, "width": 640, "height": 480},
    "table": {"pose": {"t": [0.0, 0.1, 0.8], "q": [0.0, 1.0, 0.0, 0.0]}},
    "image": "bg.png",
    "objects": [
      {"id": "box_0", "model": "cereal", "size": [0.1, 0.2, 0.3],
       "pose": {"t": [0.0, 0.1, 0.65], "q": [0.0, 1.0, 0.0, 0.0]},
       "keypoints": {"model": [[0.05, 0.1, 0.15], [0.0, 0.0, 0.0]], "image": [[300.0, 200.0], [320.0, 240.0]]}},
      {"id": "box_1", "model": "tea", "size": [0.1, 0.1, 0.1],
       "pose": {"t": [0.2, 0.1, 0.75], "q": [0.0, 1.0, 0.0, 0.0]}}
    ]})");
}

std::string error_of(const json& doc) {
  try {
    (void)parse_scene(doc, "scene.json", "/data");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("a valid scene is converted to the table frame", "[scene]") {
  const SceneLoad load = parse_scene(valid_doc(), "scene.json", "/data");
  CHECK(load.warnings.empty());
  const Scene& s = load.scene;
  REQUIRE(s.objects.size() == 2);
  CHECK(s.camera.fx == 615.0);
  CHECK(s.camera.width == 640);
  CHECK(s.image == std::filesystem::path("/data/bg.png"));
  // Table rotated 180° about camera x: table z = -camera z; object 0 is 0.15 m above the table top.
  const SceneObject& o = s.objects[0];
  CHECK(o.pose.t.x() == Approx(0.0).margin(1e-12));
  CHECK(o.pose.t.y() == Approx(0.0).margin(1e-12));
  CHECK(o.pose.t.z() == Approx(0.15));
  CHECK(o.obb().min_z() == Approx(0.0).margin(1e-12));
  CHECK(std::abs(o.pose.q.w()) == Approx(1.0));  // same orientation as the table
  CHECK(s.objects[1].pose.t.x() == Approx(0.2));
  CHECK(s.objects[1].pose.t.z() == Approx(0.05));
  REQUIRE(o.keypoints_model.size() == 2);
  CHECK(o.keypoints_image[1].x() == 320.0);
  CHECK(s.objects[1].keypoints_model.empty());
  CHECK(s.depth_noise == 0.0);  // not given: not known
  // Round trip back to the camera frame.
  CHECK((s.camera_pose(o).t - Eigen::Vector3d(0.0, 0.1, 0.65)).norm() < 1e-12);
}

TEST_CASE("scene errors name the file and JSON path", "[scene]") {
  json d = valid_doc();
  d["objects"][1]["pose"]["q"] = {0.0, 0.0, 0.0, 0.0};
  CHECK(error_of(d) == "scene.json: objects[1].pose.q: zero quaternion");

  d = valid_doc();
  d["objects"][0].erase("size");
  CHECK(error_of(d) == "scene.json: objects[0].size: missing field");

  d = valid_doc();
  d["objects"][0]["size"][2] = -0.1;
  CHECK(error_of(d) == "scene.json: objects[0].size[2]: size must be > 0, got -0.1");

  d = valid_doc();
  d["objects"][0]["size"][0] = 0.0;
  CHECK(error_of(d).rfind("scene.json: objects[0].size[0]: size must be > 0", 0) == 0);

  d = valid_doc();
  d["objects"][0]["pose"]["t"][1] = "x";
  CHECK(error_of(d) == "scene.json: objects[0].pose.t[1]: expected a number, got string");

  d = valid_doc();
  d["objects"][0]["pose"]["t"][1] = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of(d) == "scene.json: objects[0].pose.t[1]: not a finite number");

  d = valid_doc();
  d["table"]["pose"]["t"][0] = std::numeric_limits<double>::infinity();
  CHECK(error_of(d) == "scene.json: table.pose.t[0]: not a finite number");

  d = valid_doc();
  d["objects"][0]["keypoints"]["image"].erase(1);
  CHECK(error_of(d) == "scene.json: objects[0].keypoints: keypoint lists differ in length: model has 2, image has 1");

  d = valid_doc();
  d["objects"][1]["id"] = "box_0";
  CHECK(error_of(d) == "scene.json: objects[1].id: duplicate id \"box_0\"");

  d = valid_doc();
  d["objects"][1]["id"] = "table";
  CHECK(error_of(d) == "scene.json: objects[1].id: id \"table\" is reserved for the table");

  d = valid_doc();
  d["objects"] = json::array();
  CHECK(error_of(d) == "scene.json: objects: empty scene: no objects");

  d = valid_doc();
  d.erase("camera");
  CHECK(error_of(d) == "scene.json: camera: missing field");

  d = valid_doc();
  d["camera"]["width"] = 640.5;
  CHECK(error_of(d) == "scene.json: camera.width: expected an integer, got number");

  d = valid_doc();
  d["camera"]["fx"] = 0;
  CHECK(error_of(d) == "scene.json: camera.fx: must be > 0, got 0");

  d = valid_doc();
  d["objects"][0]["pose"]["q"] = {1.0, 0.0};
  CHECK(error_of(d) == "scene.json: objects[0].pose.q: expected 4 numbers, got 2");

  d = valid_doc();
  d["objects"] = json::object();
  CHECK(error_of(d) == "scene.json: objects: expected an array, got object");

  d = valid_doc();
  d["objects"][0]["keypoints"]["model"][0] = {1.0, 2.0};
  CHECK(error_of(d) == "scene.json: objects[0].keypoints.model[0]: expected 3 numbers, got 2");
}

TEST_CASE("depth_noise: the sensor's noise in metres, when the scene states it", "[scene]") {
  json d = valid_doc();
  d["depth_noise"] = 0.0023;
  CHECK(parse_scene(d, "scene.json", "/data").scene.depth_noise == 0.0023);
  d["depth_noise"] = 0;
  CHECK(error_of(d) == "scene.json: depth_noise: must be > 0, got 0");
  d["depth_noise"] = 2.5;
  CHECK(error_of(d) == "scene.json: depth_noise: 2.5 m is not a depth noise (> 1 m)");
  d["depth_noise"] = "2 mm";
  CHECK(error_of(d) == "scene.json: depth_noise: expected a number, got string");
}

TEST_CASE("non-unit quaternions are normalised with a warning", "[scene]") {
  json d = valid_doc();
  d["objects"][1]["pose"]["q"] = {0.0, 2.0, 0.0, 0.0};
  const SceneLoad load = parse_scene(d, "scene.json", "/data");
  REQUIRE(load.warnings.size() == 1);
  CHECK(load.warnings[0] == "scene.json: objects[1].pose.q: non-unit quaternion (norm 2), normalised");
  CHECK(load.scene.objects[1].pose.q.norm() == Approx(1.0));
  CHECK(load.scene.objects[1].pose.t.z() == Approx(0.05));
}

TEST_CASE("load_scene reports unreadable and malformed files by name", "[scene]") {
  const auto dir = std::filesystem::path(KSMC_BINARY_DIR) / "test_tabletop_scene_tmp";
  std::filesystem::create_directories(dir);
  CHECK_THROWS_WITH(load_scene(dir / "missing.json"), Catch::Contains("missing.json: cannot open file"));
  {
    std::ofstream(dir / "broken.json") << "{\"camera\": [1, 2";
  }
  CHECK_THROWS_WITH(load_scene(dir / "broken.json"), Catch::Contains("broken.json: invalid JSON"));
  {
    std::ofstream(dir / "ok.json") << valid_doc().dump();
  }
  const SceneLoad load = load_scene(dir / "ok.json");
  CHECK(load.scene.image == dir / "bg.png");
}

TEST_CASE("mutated documents give a SceneError or a valid scene, never anything else", "[scene][property]") {
  std::mt19937_64 rng(99);
  const std::vector<json> junk = {json(nullptr), json("x"), json(-1), json(0), json(1e308), json::array(),
                                  json::object(), json::array({1, 2}), json(true), json(2.5)};
  // Every path to a value in the valid document.
  std::vector<json::json_pointer> paths;
  const json flat = valid_doc().flatten();
  for (auto it = flat.begin(); it != flat.end(); ++it) {
    json::json_pointer p(it.key());
    while (!p.empty()) {
      paths.push_back(p);
      p = p.parent_pointer();
    }
  }
  int errors = 0, ok = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    json d = valid_doc();
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const auto& p = paths[rng() % paths.size()];
      if (!d.contains(p)) continue;
      if (rng() % 4 == 0) {
        json& parent = d[p.parent_pointer()];
        if (parent.is_object()) parent.erase(p.back());
      } else {
        d[p] = junk[rng() % junk.size()];
      }
    }
    try {
      const SceneLoad load = parse_scene(d, "scene.json", "/data");
      for (const auto& o : load.scene.objects) {
        REQUIRE(o.size.minCoeff() > 0.0);
        REQUIRE(std::abs(o.pose.q.norm() - 1.0) < 1e-9);
        REQUIRE(o.keypoints_model.size() == o.keypoints_image.size());
      }
      ++ok;
    } catch (const SceneError& e) {
      REQUIRE(std::string(e.what()).rfind("scene.json: ", 0) == 0);
      ++errors;
    }
  }
  CHECK(errors > 1000);
  CHECK(ok > 10);
}

TEST_CASE("huge values are rejected or normalised without overflow", "[scene]") {
  json d = valid_doc();
  d["objects"][0]["pose"]["q"] = {0.0, 1e308, 1e308, 0.0};
  const SceneLoad load = parse_scene(d, "scene.json", "/data");
  CHECK(load.scene.objects[0].pose.q.norm() == Approx(1.0));
  const Eigen::Quaterniond qc = load.scene.camera_pose(load.scene.objects[0]).q;
  CHECK(std::abs(qc.x()) == Approx(std::sqrt(0.5)));
  CHECK(std::abs(qc.y()) == Approx(std::sqrt(0.5)));
  REQUIRE(load.warnings.size() == 1);
  CHECK(load.warnings[0] == "scene.json: objects[0].pose.q: non-unit quaternion (norm 1.41421e+308), normalised");
  d = valid_doc();
  d["objects"][1]["pose"]["t"][2] = 1e300;
  CHECK(error_of(d) == "scene.json: objects[1].pose.t[2]: value 1e+300 out of range (|v| > 1000000)");
  d = valid_doc();
  d["camera"]["cx"] = -1e300;
  CHECK(error_of(d) == "scene.json: camera.cx: value -1e+300 out of range (|v| > 1e7)");
}

TEST_CASE("numeric ids are accepted; a duplicate across types is refused", "[scene]") {
  json d = valid_doc();
  d["objects"][0]["id"] = 7;
  d["objects"][1]["id"] = 2.5;
  const SceneLoad load = parse_scene(d, "scene.json", "/data");
  REQUIRE(load.scene.objects.size() == 2);
  CHECK(load.scene.objects[0].id == "7");
  CHECK(load.scene.objects[0].numeric_id);
  CHECK(load.scene.objects[1].id == "2.5");
  CHECK(load.scene.objects[1].numeric_id);
  d["objects"][1]["id"] = "7";  // the same constant name as the number 7
  CHECK(error_of(d) == "scene.json: objects[1].id: duplicate id \"7\"");
  d["objects"][1]["id"] = json::array({1});
  CHECK(error_of(d) == "scene.json: objects[1].id: expected a string or a number, got array");
}
