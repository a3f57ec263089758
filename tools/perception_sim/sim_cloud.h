// Simulated clouds for the point-cloud front end: a physics-generated scene (tools/tabletop_sim,
// no hidden or false estimates: the sensor sees what is there) rendered as a depth
// cloud, and the front end's boxes scored against the settled boxes (camera frame).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "stdlib/tabletop/perception/scene_from_cloud.h"
#include "stdlib/tabletop/perception/truth_eval.h"
#include "tools/tabletop_sim/depth_render.h"
#include "tools/tabletop_sim/generator.h"

namespace ksmc::tools::perception_sim {

namespace sim = tools::tabletop_sim;
using stdlib::tabletop::Camera;
using stdlib::tabletop::perception::Points;
using stdlib::tabletop::perception::TruthBox;

struct SimFamily {
  std::string name;
  sim::GeneratorOptions generator;
  sim::DepthParams depth;
};

// "singles" (one box per column, none leaning), "propped" (singles, 40 % dropped leaning
// on a neighbour), "stacks" (columns of 1-3 boxes), each with `min_objects..max_objects`.
std::vector<SimFamily> sim_families(int min_objects, int max_objects);

struct SimFrame {
  sim::GeneratedScene scene;
  Points cloud;                 // camera frame
  std::vector<TruthBox> truth;  // settled boxes, camera frame
};

SimFrame simulate_frame(std::uint64_t seed, const SimFamily& family);

// Camera intrinsics of the simulated sensor as a Scene camera (written to scene.json).
Camera scene_camera(const sim::Camera& c);

}  // namespace ksmc::tools::perception_sim
