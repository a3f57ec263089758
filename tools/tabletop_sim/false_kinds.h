// False estimates a pose estimator makes besides a box in the wrong place (corruption.h):
// a shifted copy of a real box, a duplicated detection, a box of the wrong size, a box
// flipped by 90 degrees. Each returns the false OBB (before pose noise), or nullopt when the
// drawn variant would not be observably wrong (the caller then skips it).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::tabletop_sim {

struct FalseKindParams {
  // Odds of shifted copy, duplicated detection, wrong size, flipped by 90 degrees.
  std::array<double, 4> odds{1.0, 1.0, 1.0, 1.0};
  double min_shift = 0.015;          // m, penetration of a shifted copy into its original
  double max_shift = 0.04;
  double min_duplicate_offset = 0.006;  // m, a duplicated detection's offset from the original
  double max_duplicate_offset = 0.012;
  double min_duplicate_turn = 0.035;    // rad (2 deg)
  double max_duplicate_turn = 0.105;    // rad (6 deg)
  double min_size_error = 0.016;        // m, change of the vertical extent of a wrong size
  double min_flip_change = 0.016;       // m, change of the vertical extent of a flipped box
};

enum class ExtraKind { shifted_copy, duplicate, wrong_size, flipped };
inline constexpr std::array<ExtraKind, 4> kExtraKinds{ExtraKind::shifted_copy, ExtraKind::duplicate,
                                                      ExtraKind::wrong_size, ExtraKind::flipped};

// A copy of `original` (same size and orientation) shifted sideways until it penetrates the
// original by a drawn depth.
std::optional<Box> shifted_copy(Rng& rng, const Box& original, const FalseKindParams& params);

// A second detection of `original`: a few millimetres off and a few degrees turned.
std::optional<Box> duplicate_detection(Rng& rng, const Box& original, const FalseKindParams& params);

// The estimate of `original` with a wrong size: the vertical extent (and maybe one more)
// scaled, the centre kept, so the box sinks into or floats above what it rests on.
std::optional<Box> wrong_size(Rng& rng, const Box& original, const FalseKindParams& params);

// The estimate of `original` turned by 90 degrees about one of its horizontal axes.
std::optional<Box> flipped(Rng& rng, const Box& original, const FalseKindParams& params);

}  // namespace ksmc::tools::tabletop_sim
