// The stereo front end on synthesised pairs: every box whose visible texture holds enough
// matched keypoints is found with its centre within 1 cm and its rotation within 3 degrees.
#include <catch2/catch.hpp>

#include <cstdio>

#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"
#include "stereo_scenes.h"

namespace ts = ksmc::tests::stereo;
namespace st = ksmc::stdlib::tabletop::perception::stereo;

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
      CHECK(o.keypoints_image.size() >= 6);
    }
  }
}
