// The scene the table-top blocks read (blocks::Scene of docs/binding.md §4): the constants
// of the domain's object type are the bodies, the table (constant 0) then the scene's objects
// in file order; `se3(c)` / `vec3(c)` are the pose and the size of constant c, as generated
// code passes them (`s.se3(c[0])`).
//
// Geometry is cached per body (its OBB) and per unordered pair of bodies (PairGeometry: exact
// distance, penetration depth, ...), so the contact, intersect and hover blocks of one pair
// share one computation, as the hand-written extraction did. The kit moves a body with
// set_pose (its OBB and its pairs become stale) and takes a rejected move back with undo
// (the previous geometry is restored, not recomputed).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/keypoint_fit.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pair_geometry.h"
#include "stdlib/tabletop/pose.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::blocks {

// `pose[o]` / `size[o]` of one constant: the value and whose it is (blocks use the cached
// geometry when both arguments of a box are one body's).
struct Se3 {
  std::int32_t body = -1;
  const Pose* pose = nullptr;
};
struct Vec3 {
  std::int32_t body = -1;
  const Eigen::Vector3d* size = nullptr;
};

class Scene {
 public:
  explicit Scene(tabletop::Scene input);

  // The input scene with the current object poses (likelihood, outputs).
  const tabletop::Scene& input() const noexcept { return input_; }
  // Bodies: the table, then the objects (object i is body i + 1).
  std::size_t bodies() const noexcept { return input_.objects.size() + 1; }
  static std::int32_t body_of_object(std::size_t object) { return static_cast<std::int32_t>(object + 1); }
  // Constant names for the Markov logic outputs: "table", then the object ids.
  std::vector<std::string> names() const;

  Se3 se3(std::int32_t c) const { return {c, &pose(c)}; }
  Vec3 vec3(std::int32_t c) const { return {c, &size(c)}; }
  const Pose& pose(std::int32_t c) const;
  const Eigen::Vector3d& size(std::int32_t c) const;
  bool is_table(std::int32_t c) const { return c == 0; }

  // Cached OBB of body c.
  const Obb& box(std::int32_t c) const;
  // Cached geometry of bodies a != b (`direction` from the lower to the higher body index);
  // the distance is exact whenever it is at most `exact_below`.
  const PairGeometry& pair(std::int32_t a, std::int32_t b, double exact_below) const;

  // The pose body c's keypoints imply (keypoint_fit.h), fitted from the input estimate on
  // first use; not ok for the table and for objects with fewer than four keypoints.
  const KeypointFit& fit(std::int32_t c) const;

  // The near-vertical contact / intersect tolerance of this scene [m]: 3 standard deviations
  // of its resting gaps (gap_noise.h) within [5 mm, 15 mm], from the input poses; or of the
  // scene's depth noise when known (Scene::depth_noise, the cloud front end's scenes).
  double vertical_tolerance() const noexcept { return vertical_tolerance_; }
  // One standard deviation of the scene's resting gaps [m] (gap_noise.h), from the input
  // poses, or its depth noise when known; a third of vertical_tolerance() when too few gaps
  // were seen to judge.
  double gap_sigma() const noexcept { return gap_sigma_; }
  // One standard deviation of the scene's resting tilts [rad] (tilt_noise.h), from the input
  // poses; infinite when fewer than 3 objects rest on a face (too few to judge).
  double tilt_sigma() const noexcept { return tilt_sigma_; }

  // Moves object body c (c >= 1). One move at a time: commit() keeps it, undo() restores the
  // previous pose and geometry.
  void set_pose(std::int32_t c, const Pose& pose);
  void commit() { undo_.active = false; }
  void undo();

  // A per-body value a block derives from body c and the bodies around it, under `key` (its
  // tolerance), kept until the next set_pose or undo: one move's extraction then computes it
  // once per body, not once per atom that reads it (blocks.cpp: seat_gap). Empty when not
  // known for this key.
  std::optional<double> memo(std::int32_t c, double key) const;
  void set_memo(std::int32_t c, double key, double value) const;

  // Tolerances the hover block was evaluated with (the kit re-evaluates hover atoms of bodies
  // whose touching status with a moved body changes; blocks.h: touching).
  const std::vector<double>& hover_tolerances() const noexcept { return hover_eps_; }
  void note_hover_tolerance(double eps) const;
  // The tolerances of the last stable / contact / intersect block calls (stdlib defaults for
  // a block never called): the scene graph's support and contact edges use them.
  const EvidenceParams& relation_params() const noexcept { return params_; }
  EvidenceParams& relation_params_mut() const noexcept { return params_; }

 private:
  struct PairSlot {
    PairGeometry g;
    double exact_below = 0.0;
    bool valid = false;
  };
  std::size_t slot(std::int32_t a, std::int32_t b) const;

  tabletop::Scene input_;
  Pose table_pose_;
  std::vector<Pose> input_poses_;                     // per object, as given
  mutable std::vector<std::optional<KeypointFit>> fits_;  // per body, on first use
  double vertical_tolerance_ = 0.0;
  double gap_sigma_ = 0.0;
  double tilt_sigma_ = std::numeric_limits<double>::infinity();
  mutable std::vector<Obb> boxes_;
  mutable std::vector<char> box_valid_;
  mutable std::vector<PairSlot> pairs_;  // [min][max], n x n
  mutable std::vector<double> hover_eps_;
  mutable double memo_key_ = 0.0;
  mutable std::vector<double> memo_;
  mutable std::vector<char> memo_valid_;
  mutable EvidenceParams params_;
  struct Undo {
    bool active = false;
    std::int32_t body = -1;
    Pose pose;
    Obb box;
    char box_valid = 0;
    std::vector<PairSlot> row;  // slot(body, j) for every j
  } undo_;
};

}  // namespace ksmc::stdlib::tabletop::blocks
