// True physical relations of a settled configuration: stable pose, stable support
// (A rests on B's top face) and unstable contact (touching, but not a support).
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "tools/tabletop_sim/box_geometry.h"

namespace ksmc::tools::tabletop_sim {

inline constexpr int kTableIndex = -1;  // stands for the table in relation pairs

struct RelationParams {
  double stable_tolerance = 0.0523598776;  // rad (3 deg): a box axis this close to vertical
  double support_gap = 0.002;              // m: |bottom of A - top face of B|
  double min_support_area = 1e-4;          // m^2 (1 cm^2) of A's bottom face over B's top face
  double contact_gap = 0.002;              // m: boxes this close touch
};

struct Relations {
  std::vector<bool> stable;                  // per box
  std::vector<std::pair<int, int>> support;  // (upper, lower), lower may be kTableIndex; sorted
  std::vector<std::pair<int, int>> contact;  // (a, b), a < b or b == kTableIndex; sorted; no support pairs
};

bool is_stable(const Box& b, double tolerance);

// Geometry of "upper rests on lower's top face": the gap between upper's lowest vertex and the
// plane of lower's upward face, and the area of upper's bottom face lying over that face.
struct SupportGeometry {
  double gap = 0.0;   // m, negative when penetrating
  double area = 0.0;  // m^2
};
SupportGeometry support_geometry(const Box& upper, const Box& lower);

Relations compute_relations(std::span<const Box> boxes, const RelationParams& params);

}  // namespace ksmc::tools::tabletop_sim
