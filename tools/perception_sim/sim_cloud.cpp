#include "tools/perception_sim/sim_cloud.h"

namespace ksmc::tools::perception_sim {

std::vector<SimFamily> sim_families(int min_objects, int max_objects) {
  auto base = [&](std::string name) {
    SimFamily f;
    f.name = std::move(name);
    f.generator.min_objects = min_objects;
    f.generator.max_objects = max_objects;
    f.generator.corruption.hidden_rate = 0.0;
    f.generator.corruption.false_rate = 0.0;
    return f;
  };
  SimFamily singles = base("singles");
  singles.generator.layout.stack_height_odds = {1.0, 0.0, 0.0};
  singles.generator.layout.lean_rate = 0.0;
  SimFamily propped = base("propped");
  propped.generator.layout.stack_height_odds = {1.0, 0.0, 0.0};
  propped.generator.layout.lean_rate = 0.4;
  SimFamily stacks = base("stacks");
  stacks.generator.layout.lean_rate = 0.0;
  return {singles, propped, stacks};
}

SimFrame simulate_frame(std::uint64_t seed, const SimFamily& family) {
  SimFrame f;
  f.scene = sim::generate_scene(seed, family.generator);
  std::vector<sim::Box> boxes;
  for (const auto& p : f.scene.physical) boxes.push_back(p.body.box);
  sim::Rng rng(sim::mix_seed(seed, 0xD3E7));
  f.cloud = sim::render_depth(rng, f.scene.camera, f.scene.table_from_camera, boxes, family.generator.table,
                              family.depth);
  const sim::Pose camera_from_table = f.scene.table_from_camera.inverse();
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const sim::Pose p = camera_from_table * boxes[i].pose;
    f.truth.push_back({std::string(f.scene.physical[i].item.model) + "#" + std::to_string(i), p.t, p.rotation(),
                       boxes[i].size});
  }
  return f;
}

Camera scene_camera(const sim::Camera& c) { return Camera{c.fx, c.fy, c.cx, c.cy, c.width, c.height}; }

}  // namespace ksmc::tools::perception_sim
