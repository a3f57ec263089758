// Turning a true settled configuration into an imperfect estimate: undetected supporting boxes
// (which leave the boxes on them floating = hidden), injected false estimates, pose noise.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "tools/tabletop_sim/catalogue.h"
#include "tools/tabletop_sim/false_kinds.h"
#include "tools/tabletop_sim/relations.h"

namespace ksmc::tools::tabletop_sim {

struct CorruptionParams {
  double hidden_rate = 0.3;          // chance that a supporting box goes undetected
  double false_rate = 0.1;           // chance per detected box of one extra false estimate
  double sigma_translation = 0.003;  // m, RMS length of the translation noise
  double sigma_rotation = 0.0261799; // rad (1.5 deg), RMS angle of the rotation noise
  double min_hidden_height = 0.01;   // m, a hidden box's lowest point above the table
  double min_penetration = 0.015;    // m, drawn penetration of an intersecting false estimate
  double max_penetration = 0.04;
  double min_float_gap = 0.022;      // m, clearance of a floating false estimate to everything
  double min_float_tilt = 0.2094395; // rad (12 deg)
  double max_float_tilt = 0.6981317; // rad (40 deg)
  // Share of false estimates drawn from the further kinds of false_kinds.h (shifted copy,
  // duplicated detection, wrong size, flipped) instead of the four kinds above.
  double extra_kind_rate = 0.0;
  FalseKindParams extra_kinds;
};

// Marks supporting boxes as undetected with probability hidden_rate, keeping only removals that
// leave every affected box either still supported or clearly floating (hidden), and never
// leave a box that merely leaned on the removed one without any contact.
std::vector<bool> choose_undetected(Rng& rng, std::span<const Box> boxes, const Relations& rel,
                                    const CorruptionParams& params);

// True when, with the `removed` boxes missing from the estimate, every present box either still
// touches something present (table included) or is hidden more than min_hidden_height above
// the table. Used for undetected supporters and for boxes whose estimate is moved away.
bool estimate_is_consistent(std::span<const Box> boxes, const Relations& rel, const std::vector<bool>& removed,
                            const CorruptionParams& params);

// Boxes present in the estimate whose every supporter was removed (and that are not on the table).
std::vector<bool> hidden_boxes(std::size_t count, const Relations& rel, const std::vector<bool>& removed);

enum class FalseKind {
  none, extra_intersecting, moved_intersecting, extra_floating, moved_floating,
  shifted_copy, duplicate, wrong_size, flipped
};
std::string_view to_string(FalseKind kind);

struct FalseEstimate {
  FalseKind kind = FalseKind::none;
  int moved = -1;  // physical box whose estimate is replaced (moved_* kinds), else -1
  BoxItem item;    // model and size of the estimate
  Box box;         // the false pose (before noise)
};

// Places a false estimate of `item` intersecting `target` by a drawn depth, or nullopt.
std::optional<Box> place_intersecting(Rng& rng, const BoxItem& item, const Box& target, const CorruptionParams& params);

// Places a tilted false estimate of `item` floating clear of every box in `others`, or nullopt.
std::optional<Box> place_floating(Rng& rng, const BoxItem& item, std::span<const Box> others,
                                  const Eigen::Vector2d& region, const CorruptionParams& params);

// Adds pose noise: translation and rotation vectors with per-axis sigma / sqrt(3).
Pose add_pose_noise(Rng& rng, const Pose& pose, const CorruptionParams& params);

}  // namespace ksmc::tools::tabletop_sim
