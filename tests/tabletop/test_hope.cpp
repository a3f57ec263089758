// The real HOPE-Video frame (10 objects standing on a table, nothing stacked):
// converted to a scene, its evidence must be the ground truth of the data README.
#include <catch2/catch.hpp>

#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/extract_stable.h"
#include "stdlib/tabletop/hope_import.h"
#include "tests/support/shared_data.h"

using namespace ksmc::stdlib::tabletop;

namespace {
const char* kFrame = "data/tabletop/hope_video_frame/meta_data.json";
}

TEST_CASE("HOPE frame: conversion matches the README's world-frame OBBs", "[hope]") {
  if (!ksmc::tests::have_shared(kFrame)) return;
  const HopeImport imp = import_hope_file(ksmc::tests::shared_dir() / kFrame);
  const Scene& s = imp.scene;
  REQUIRE(s.objects.size() == 10);
  CHECK(s.camera.fx == Approx(605.8222));
  CHECK(s.camera.cy == Approx(245.73769));
  CHECK(imp.table_z_world == Approx(-0.10546).margin(2e-4));
  // Cross-check against obb_world.json (derived independently): centre heights and lowest z.
  std::ifstream in(ksmc::tests::shared_dir() / "data/tabletop/hope_video_frame/obb_world.json");
  const auto ref = nlohmann::json::parse(in);
  REQUIRE(ref["objects"].size() == 10);
  for (std::size_t i = 0; i < 10; ++i) {
    const auto& r = ref["objects"][i];
    const SceneObject& o = s.objects[i];
    INFO(o.id);
    CHECK(o.model == r["class"].get<std::string>());
    CHECK(o.pose.t.z() + imp.table_z_world == Approx(r["center_m"][2].get<double>()).margin(2e-5));
    CHECK(o.obb().min_z() + imp.table_z_world == Approx(r["zmin_m"].get<double>()).margin(2e-5));
    for (int a = 0; a < 3; ++a) CHECK(o.size[a] == Approx(r["size_m"][static_cast<std::size_t>(a)].get<double>()).margin(2e-5));
  }
}

TEST_CASE("HOPE frame: single-level scene evidence with default tolerances", "[hope]") {
  if (!ksmc::tests::have_shared(kFrame)) return;
  const HopeImport imp = import_hope_file(ksmc::tests::shared_dir() / kFrame);
  const Evidence ev = extract_evidence(imp.scene);
  double closest = 1e9;
  for (std::size_t a = 1; a < ev.size(); ++a) {
    INFO(ev.ids[a] << " tilt " << tilt_angle(ev.boxes[a]) * 180.0 / 3.14159265358979 << " deg, lowest z "
                   << ev.boxes[a].min_z());
    CHECK(ev.stable[a]);
    CHECK_FALSE(ev.hover[a]);
    CHECK(ev.contact[a][0]);    // on the table
    CHECK_FALSE(ev.intersect[a][0]);
    CHECK(ev.higher[a][0]);
    for (std::size_t b = 1; b < ev.size(); ++b) {
      if (a == b) continue;
      INFO("pair " << ev.ids[a] << " / " << ev.ids[b] << " distance " << ev.geometry[a][b].distance);
      CHECK_FALSE(ev.contact[a][b]);
      CHECK_FALSE(ev.intersect[a][b]);
      CHECK_FALSE(ev.higher[a][b]);
      closest = std::min(closest, ev.geometry[a][b].distance);
    }
  }
  std::cout << "HOPE frame: closest object pair " << closest * 1000.0 << " mm (exact distance)\n";
  CHECK(closest > 0.004);
}

TEST_CASE("HOPE importer: malformed metadata names the file and place", "[hope]") {
  auto error_of = [](const nlohmann::json& doc) -> std::string {
    try {
      (void)import_hope(doc, "meta_data.json");
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no error)";
  };
  const auto eye = nlohmann::json::parse("[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]");
  nlohmann::json doc = {
      {"camera", {{"intrinsics", nlohmann::json::parse("[[600,0,320],[0,600,240],[0,0,1]]")},
                  {"extrinsics", eye}, {"width", 640}, {"height", 480}}},
      {"objects", nlohmann::json::array({{{"class", "Milk"},
                                          {"pose", nlohmann::json::parse("[[1,0,0,0],[0,1,0,0],[0,0,1,50],[0,0,0,1]]")},
                                          {"bbox3d", {-3, -9, -3, 3, 9, 3}}}})}};
  const HopeImport ok = import_hope(doc, "meta_data.json");
  REQUIRE(ok.scene.objects.size() == 1);
  CHECK(ok.scene.objects[0].size.isApprox(Eigen::Vector3d(0.06, 0.18, 0.06)));
  CHECK(ok.scene.objects[0].obb().min_z() == Approx(0.0).margin(1e-12));  // table at the lowest point

  nlohmann::json d = doc;
  d.erase("camera");
  CHECK(error_of(d) == "meta_data.json: camera: missing field");
  d = doc;
  d["objects"][0]["bbox3d"] = {1, 2, 3};
  CHECK(error_of(d) == "meta_data.json: objects[0].bbox3d: expected 6 numbers, got 3");
  d = doc;
  d["objects"][0]["pose"][0][0] = 2.0;
  CHECK(error_of(d) == "meta_data.json: objects[0].pose: rotation part is not a proper rotation");
  d = doc;
  d["objects"][0]["bbox3d"][3] = -5;
  CHECK(error_of(d) == "meta_data.json: objects[0].bbox3d: max must exceed min on axis 0");
  d = doc;
  d["objects"] = nlohmann::json::array();
  CHECK(error_of(d) == "meta_data.json: objects: empty scene: no objects");
  CHECK_THROWS_WITH(import_hope_file("/nonexistent/meta.json"), Catch::Contains("/nonexistent/meta.json: cannot open file"));
}
