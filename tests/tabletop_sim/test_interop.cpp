// Generated scenes read back through the tabletop domain's own scene.json reader
// (stdlib/tabletop/scene_io.h): no errors, no warnings, same objects in the same frames.
#include <catch2/catch.hpp>

#include <filesystem>

#include "stdlib/tabletop/scene_io.h"
#include "tools/tabletop_sim/scene_writer.h"

namespace sim = ksmc::tools::tabletop_sim;
namespace tt = ksmc::stdlib::tabletop;
namespace fs = std::filesystem;

TEST_CASE("Generated scenes load with the tabletop scene reader in the same table frame", "[tabletop_sim][interop]") {
  const fs::path dir = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_interop";
  fs::remove_all(dir);
  fs::create_directories(dir);
  sim::GeneratorOptions o;
  o.min_objects = 3;
  o.max_objects = 12;
  o.corruption.false_rate = 0.2;
  for (int i = 0; i < 6; ++i) {
    const auto scene = sim::generate_scene(sim::scene_seed(31, static_cast<std::uint64_t>(i)), o);
    const std::string stem = "scene_00" + std::to_string(i);
    sim::write_scene_files(dir, stem, scene);
    INFO(stem);
    const tt::SceneLoad load = tt::load_scene(dir / (stem + ".json"));
    CHECK(load.warnings.empty());
    const tt::Scene& s = load.scene;
    CHECK(s.camera.fx == 615.0);
    CHECK(s.camera.width == 640);
    REQUIRE(s.objects.size() == scene.objects.size());
    for (std::size_t k = 0; k < s.objects.size(); ++k) {
      const auto& a = s.objects[k];
      const auto& b = scene.objects[k];
      CHECK(a.id == b.id);
      CHECK(a.model == std::string(b.item.model));
      CHECK((a.size - b.item.size).norm() < 2e-5);
      // The reader expresses poses in the table frame: it must recover our table-frame estimate.
      CHECK((a.pose.t - b.estimate.t).norm() < 1e-5);
      CHECK(sim::rotation_angle(a.pose.q, b.estimate.q) < 1e-6);
      REQUIRE(a.keypoints_model.size() == b.keypoints.model.size());
      for (std::size_t j = 0; j < a.keypoints_image.size(); ++j) {
        CHECK((a.keypoints_image[j] - b.keypoints.image[j]).norm() < 1e-3);
        CHECK((a.keypoints_model[j] - b.keypoints.model[j]).norm() < 1e-5);
      }
    }
  }
}
