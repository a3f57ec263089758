// One complete synthetic table-top scene: drop and settle boxes (Bullet), derive the true
// support/contact graph, hide supporters, inject false estimates, add noise and keypoints.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tools/tabletop_sim/camera.h"
#include "tools/tabletop_sim/corruption.h"
#include "tools/tabletop_sim/layout.h"

namespace ksmc::tools::tabletop_sim {

struct GeneratorOptions {
  int min_objects = 3;   // physical boxes dropped (before hiding / false injection)
  int max_objects = 25;
  int max_attempts = 60; // redraws (unsettled, fallen, unplaceable, unseen) before giving up
  TableSpec table;
  LayoutParams layout;
  SettleParams settle;
  RelationParams relations;
  CorruptionParams corruption;
  CameraPlacement camera_placement;
  KeypointParams keypoints;
  Camera camera;
  bool numeric_ids = false;  // ids 0, 1, ... written as JSON numbers instead of "box_0", ...
};

// Throws std::invalid_argument naming the offending option.
void validate(const GeneratorOptions& options);

// A box that physically exists in the settled scene.
struct PhysicalBox {
  BoxItem item;
  SimBody body;          // body.box.pose is the settled (true) pose, table frame
  bool undetected = false;  // removed from the estimate (it is what hidden boxes rest on)
};

// An entry of the written scene.
struct SceneObject {
  std::string id;
  BoxItem item;
  int physical = -1;                 // index into GeneratedScene::physical, -1 for an extra false box
  FalseKind false_kind = FalseKind::none;
  bool hidden = false;
  bool stable = false;               // true stable pose of a real box (false for false estimates)
  Pose clean_pose;                   // table frame: true pose, or the false pose (before noise)
  Pose estimate;                     // table frame, with pose noise: what the scene file states
  Keypoints keypoints;
};

struct GeneratedScene {
  std::uint64_t seed = 0;
  bool numeric_ids = false;          // ids are written as JSON numbers
  Camera camera;
  Pose table_from_camera;            // camera pose in the table frame
  std::vector<PhysicalBox> physical;
  Relations relations;               // over `physical` (indices), true configuration
  std::vector<SceneObject> objects;  // in output order (ids box_0, box_1, ...)
  std::vector<std::pair<std::string, std::string>> support;  // (upper, lower) ids, "table" allowed
  std::vector<std::pair<std::string, std::string>> contact;
  int attempts = 0;                  // 1 = first draw settled
  double settle_time = 0.0;          // simulated seconds of the accepted draw
  std::vector<std::string> redraws;  // reason for each rejected draw

  bool is_false(std::size_t i) const { return objects[i].false_kind != FalseKind::none; }
  std::size_t hidden_count() const;
  std::size_t false_count() const;
};

// Deterministic in (seed, options). Throws std::runtime_error, naming each reason with its
// count, after 2 x max_attempts redraws (the second round in a drop region half as wide again).
GeneratedScene generate_scene(std::uint64_t seed, const GeneratorOptions& options);

// Seed of scene `index` in a batch started with `seed`.
inline std::uint64_t scene_seed(std::uint64_t seed, std::uint64_t index) { return mix_seed(seed, index); }

}  // namespace ksmc::tools::tabletop_sim
