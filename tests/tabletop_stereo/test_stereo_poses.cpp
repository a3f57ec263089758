// The stereo front end on synthesised pairs: every box whose visible texture holds enough
// matched keypoints is found with its centre within 1 cm and its rotation within 3 degrees.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "stdlib/tabletop/perception/scene_json.h"
#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"
#include "stdlib/tabletop/scene_io.h"
#include "stereo_scenes.h"

namespace ts = ksmc::tests::stereo;
namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace pc = ksmc::stdlib::tabletop::perception;

TEST_CASE("stereo: poses of textured boxes recovered from a synthesised pair", "[stereo]") {
  for (std::uint64_t seed : {1u, 2u}) {
    const auto boxes = ts::grid_boxes(6, seed);
    const ts::sy::Rig rig = ts::standard_rig();
    const auto pair = ts::sy::render_pair(rig, boxes, seed);
    const auto dir = ts::fresh_dir("poses");
    for (const auto& b : boxes) ts::sy::write_object_folder(dir / "db", b);
    const auto db = st::load_database(dir / "db");
    const auto calib = ts::sy::rig_calib(rig);
    const st::StereoScene s = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db);
    INFO("seed " << seed << ": stereo points " << s.points.point.size());
    CHECK(s.points.point.size() > 200);
    CHECK(s.scene.objects.size() >= 5);  // state: at least 5 of 6 boxes have enough visible texture
    for (std::size_t i = 0; i < s.scene.objects.size(); ++i) {
      const auto& o = s.scene.objects[i];
      const auto& truth = boxes[static_cast<std::size_t>(s.detections[i].object)];
      const double dc = (o.pose.t - truth.pose.t).norm();
      const double da = ts::angle_between(o.pose.q, truth.pose.q) * 180.0 / M_PI;
      std::printf("seed %llu %s: inliers %zu centre %.2f mm angle %.2f deg\n", static_cast<unsigned long long>(seed),
                  o.id.c_str(), s.detections[i].inliers.size(), dc * 1000.0, da);
      CHECK(o.id == truth.name);
      CHECK(dc < 0.01);
      CHECK(da < 3.0);
      CHECK(o.keypoints_image.size() == o.keypoints_model.size());
      CHECK(o.keypoints_image.size() >= static_cast<std::size_t>(st::PoseOptions{}.min_verified_inliers));
    }
  }
}

TEST_CASE("stereo: a partly hidden box with 5 tight inliers is found, boxes absent from the view are not",
          "[stereo]") {
  // The benchmark's first 10-box scene; only boxes 0-6 are rendered, the database holds all 10.
  const std::uint64_t seed = 200;
  const auto boxes = ts::grid_boxes(10, seed);
  const std::vector<ts::sy::TexturedBox> shown(boxes.begin(), boxes.begin() + 7);
  const ts::sy::Rig rig = ts::standard_rig();
  const auto pair = ts::sy::render_pair(rig, shown, seed);
  const auto dir = ts::fresh_dir("verified");
  for (const auto& b : boxes) ts::sy::write_object_folder(dir / "db", b);
  const auto db = st::load_database(dir / "db");
  const auto calib = ts::sy::rig_calib(rig);
  auto found = [&](const st::StereoSceneOptions& options) {
    const st::StereoScene s = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db, options);
    std::vector<std::size_t> in;
    for (std::size_t i = 0; i < s.scene.objects.size(); ++i) {
      const auto k = static_cast<std::size_t>(s.detections[i].object);
      in.push_back(k);
      CHECK(k < shown.size());  // no box that is not in the view
      CHECK((s.scene.objects[i].pose.t - boxes[k].pose.t).norm() < 0.01);
    }
    return in;
  };
  st::StereoSceneOptions strict;
  strict.pose.min_verified_inliers = strict.pose.min_inliers;  // the verified path off
  const auto with = found({}), without = found(strict);
  INFO("found " << with.size() << " with the verified path, " << without.size() << " without");
  CHECK(with.size() == without.size() + 1);
  CHECK(std::find(with.begin(), with.end(), 6u) != with.end());     // box6: 5 inliers, rms 0.7 mm
  CHECK(std::find(without.begin(), without.end(), 6u) == without.end());
}

TEST_CASE("stereo: the front end is deterministic and its scene.json reads back", "[stereo]") {
  const auto boxes = ts::grid_boxes(4, 9);
  const ts::sy::Rig rig = ts::standard_rig();
  const auto pair = ts::sy::render_pair(rig, boxes, 9);
  const auto again = ts::sy::render_pair(rig, boxes, 9);
  CHECK(cv::norm(pair.left, again.left, cv::NORM_INF) == 0.0);  // the renderer is seeded
  const auto dir = ts::fresh_dir("determinism");
  for (const auto& b : boxes) ts::sy::write_object_folder(dir / "db", b);
  const auto db = st::load_database(dir / "db");
  const auto calib = ts::sy::rig_calib(rig);
  const auto a = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db);
  const auto b = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db);
  REQUIRE(!a.scene.objects.empty());
  const std::string text = pc::scene_json_text(a.scene);
  CHECK(text == pc::scene_json_text(b.scene));
  std::ofstream(dir / "scene.json") << text;
  const auto back = ksmc::stdlib::tabletop::load_scene(dir / "scene.json");
  REQUIRE(back.scene.objects.size() == a.scene.objects.size());
  for (std::size_t i = 0; i < a.scene.objects.size(); ++i) {
    CHECK(back.scene.objects[i].keypoints_model.size() == a.scene.objects[i].keypoints_model.size());
    CHECK((back.scene.objects[i].pose.t - a.scene.objects[i].pose.t).norm() < 1e-5);
  }
}

TEST_CASE("stereo: calibration round trip and epipolar geometry", "[stereo]") {
  const ts::sy::Rig rig = ts::standard_rig();
  const auto calib = ts::sy::rig_calib(rig);
  const auto dir = ts::fresh_dir("calib");
  st::save_calib(dir / "stereo.yaml", calib);
  const auto back = st::load_calib(dir / "stereo.yaml");
  CHECK(back.width == 640);
  CHECK((back.k_left - calib.k_left).norm() < 1e-9);
  CHECK((back.t - calib.t).norm() < 1e-12);
  REQUIRE(back.table_in_left);
  CHECK((back.table_in_left->t - calib.table_in_left->t).norm() < 1e-9);
  // A point seen in both cameras satisfies x_r^T F x_l = 0 and triangulates back.
  const Eigen::Vector3d p(0.05, -0.02, 0.7);
  const Eigen::Vector3d pr = calib.r * p + calib.t;
  const Eigen::Vector3d l = calib.k_left * p, r = calib.k_right * pr;
  const Eigen::Vector2d ul = l.head<2>() / l.z(), ur = r.head<2>() / r.z();
  CHECK(std::abs(Eigen::Vector3d(ur.x(), ur.y(), 1).dot(calib.fundamental() * Eigen::Vector3d(ul.x(), ul.y(), 1))) < 1e-9);
  CHECK((st::triangulate(calib, ul, ur) - p).norm() < 1e-9);
}

TEST_CASE("stereo: without a table in the calibration the table plane is fitted to the stereo points", "[stereo]") {
  const auto boxes = ts::grid_boxes(6, 2);
  const ts::sy::Rig rig = ts::standard_rig();
  const auto pair = ts::sy::render_pair(rig, boxes, 2);
  const auto dir = ts::fresh_dir("table");
  for (const auto& b : boxes) ts::sy::write_object_folder(dir / "db", b);
  const auto db = st::load_database(dir / "db");
  auto calib = ts::sy::rig_calib(rig);
  const auto truth = *calib.table_in_left;
  calib.table_in_left.reset();
  const auto s = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db);
  REQUIRE(s.table);
  std::printf("table: %d of %d unclaimed stereo points, rms %.2f mm, seen %.2f x %.2f m\n", s.table->inliers,
              s.table->candidates, 1000.0 * s.table->rms, s.table->size.x(), s.table->size.y());
  const Eigen::Vector3d n = s.table->table_in_left.rotation().col(2), n_true = truth.rotation().col(2);
  CHECK(std::acos(std::min(1.0, n.dot(n_true))) * 180.0 / M_PI < 3.0);  // measured 1.8 deg
  CHECK(std::abs(n_true.dot(s.table->table_in_left.t - truth.t)) < 0.006);  // origin on the true plane; measured 3.9 mm
  REQUIRE(s.scene.objects.size() >= 5);
  for (const auto& o : s.scene.objects) {  // upright boxes standing on the fitted table, within its error
    const double tilt = std::acos(std::min(1.0, std::abs((o.pose.q * Eigen::Vector3d::UnitZ()).z()))) * 180.0 / M_PI;
    std::printf("  %s: tilt %.2f deg, bottom %.1f mm\n", o.id.c_str(), tilt, 1000.0 * (o.pose.t.z() - 0.5 * o.size.z()));
    CHECK(tilt < 4.5);
    CHECK(std::abs(o.pose.t.z() - 0.5 * o.size.z()) < 0.015);
  }
}

TEST_CASE("stereo: two copies of one product are two objects", "[stereo]") {
  // The same textured box (same name, same texture seed) twice on the table, a third box
  // beside them; the database holds the product once (and the third box).
  const ts::sy::TexturedBox copy = ts::sy::textured_box("cereal", {0.09, 0.06, 0.08}, ts::upright(-0.12, 0.0, 0.04, 0.3), 7);
  ts::sy::TexturedBox second = copy;
  second.pose = ts::upright(0.05, 0.06, 0.04, -0.4);
  const ts::sy::TexturedBox other = ts::sy::textured_box("tea", {0.08, 0.07, 0.05}, ts::upright(0.02, -0.12, 0.025, 0.1), 8);
  const std::vector<ts::sy::TexturedBox> boxes{copy, second, other};
  const ts::sy::Rig rig = ts::standard_rig();
  const auto pair = ts::sy::render_pair(rig, boxes, 5);
  const auto dir = ts::fresh_dir("copies");
  ts::sy::write_object_folder(dir / "db", copy);
  ts::sy::write_object_folder(dir / "db", other);
  const auto db = st::load_database(dir / "db");
  const st::StereoScene s = st::scene_from_images(pair.left, pair.right, "l", "r", ts::sy::rig_calib(rig), db);
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < s.scene.objects.size(); ++i) {
    const auto& o = s.scene.objects[i];
    ids.push_back(o.id);
    // Each object found is one of the boxes of its product, within 1 cm and 3 degrees.
    double best = 1e9, angle = 0.0;
    for (const auto& b : boxes) {
      if (b.name != db[static_cast<std::size_t>(s.detections[i].object)].name) continue;
      const double dc = (o.pose.t - b.pose.t).norm();
      if (dc < best) best = dc, angle = ts::angle_between(o.pose.q, b.pose.q) * 180.0 / M_PI;
    }
    std::printf("copies %s: instance %d, inliers %zu, centre %.2f mm, angle %.2f deg\n", o.id.c_str(), s.detections[i].instance,
                s.detections[i].inliers.size(), best * 1000.0, angle);
    CHECK(best < 0.01);
    CHECK(angle < 3.0);
  }
  std::sort(ids.begin(), ids.end());
  CHECK(ids == std::vector<std::string>{"cereal", "cereal_2", "tea"});
  // The two copies are two different boxes.
  REQUIRE(s.scene.objects.size() == 3);
  std::vector<Eigen::Vector3d> cereal;
  for (const auto& o : s.scene.objects)
    if (o.id.rfind("cereal", 0) == 0) cereal.push_back(o.pose.t);
  REQUIRE(cereal.size() == 2);
  CHECK((cereal[0] - cereal[1]).norm() > 0.1);

  // A database object already named cereal_2 (not in the view): the copy takes the next number.
  ts::sy::write_object_folder(dir / "db", ts::sy::textured_box("cereal_2", {0.05, 0.05, 0.05}, ts::upright(0, 0, 0.025, 0), 9));
  const auto db2 = st::load_database(dir / "db");
  const st::StereoScene s2 = st::scene_from_images(pair.left, pair.right, "l", "r", ts::sy::rig_calib(rig), db2);
  std::vector<std::string> ids2;
  for (const auto& o : s2.scene.objects) ids2.push_back(o.id);
  std::sort(ids2.begin(), ids2.end());
  CHECK(ids2 == std::vector<std::string>{"cereal", "cereal_3", "tea"});
}
