// The indoor kit's building blocks as generated code calls them (docs/binding.md §3): the
// scene view the extractors read, the moves its proposal sources make, and one C++ function
// per `extern` of stdlib/indoor.ksm, parameters in signature order, numbers in base units
// (metres, radians, cells as written). `ksmc check` has enforced the ranges and shapes of
// stdlib/indoor.ksm, so the blocks do not re-check them.
//
// A `rect` of the model is a unit of the world (its rectangle plus its id), a `segment` a
// door (its segment plus the two units it joins): the blocks need the identity to tell a unit
// from itself and to count the doors attached to it.
#pragma once

#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "runtime/domain/binding.h"
#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor::blocks {

// The kit's view of one world for generated code. Constant index i of the unit type is the
// i-th unit in world order (sorted by id).
class Scene {
 public:
  Scene(const World& world, double resolution, const ClassGrid* map = nullptr,
        const cv::Mat1f* free_distance = nullptr)
      : world_(&world), resolution_(resolution), map_(map), free_distance_(free_distance) {}

  const Unit& rect(std::int32_t i) const { return world_->units()[static_cast<std::size_t>(i)]; }
  std::span<const Unit> rects() const { return world_->units(); }
  const Door& segment(std::int32_t i) const { return world_->doors()[static_cast<std::size_t>(i)]; }
  std::span<const Door> segments() const { return world_->doors(); }
  std::size_t size() const { return world_->units().size(); }

  double resolution() const { return resolution_; }  // metres per cell
  const ClassGrid* map() const { return map_; }       // the classified map, when the kit has one
  // free_distance(map) of that map (stdlib/indoor/free_distance.h), when the kit has one.
  const cv::Mat1f* free_distance() const { return free_distance_; }
  const World& world() const { return *world_; }

 private:
  const World* world_;
  double resolution_;
  const ClassGrid* map_;
  const cv::Mat1f* free_distance_;
};

// The moves the proposal sources make (`makes F / R` in stdlib/indoor.ksm).
enum class Move { birth, death, split, merge, shrink, dilate, allocate, deallocate, interchange };

// ---- extractors ------------------------------------------------------------------------------
namespace geom {
// Table 3.6: hall-like when the longer side exceeds big_size (m); otherwise corridor-like when
// longer / shorter exceeds big_ratio, else room-like; an elongated unit at most corridor_width
// (m) wide is corridor-like at any length (classify_unit). Exactly one of the three holds.
bool room_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width);
bool corridor_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width);
bool hall_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width);
// Two different units whose walls, dilated by `dilate` cells, meet (connecting_walls); symmetric.
bool adjacent(const Scene& s, const Unit& a, const Unit& b, double dilate);
// At least `min_doors` of `doors` are attached to the unit.
bool multi_door(const Scene& s, const Unit& u, std::span<const Door> doors, int min_doors);
// The unit's shorter side is below `min_width` (m): no robot stands in it (a sliver on a wall).
bool thin(const Scene& s, const Unit& u, double min_width);
// More than `max_fraction` of the map cells inside the unit are not free (occupied or
// unknown): the unit lies on walls or outside the mapped space. Measured on a grid of up to
// 24 x 24 sample points over the unit; false without a map.
bool blocked(const Scene& s, const Unit& u, double max_fraction);
// The unit holds a region the sensor never saw into, wider than `min_width` (m): a point of the
// unit lies farther than min_width / 2 from every free cell of the map (a courtyard, a light
// well, unexplored space past an outer wall). Points are sampled every min_width / 4 over the
// unit, so a region is always found when it holds a disc 1.35 x min_width wide and never when
// it holds none min_width wide. False without the map's free distance.
bool hollow(const Scene& s, const Unit& u, double min_width);
// Two units with connecting walls (as geom.adjacent with `dilate`) whose common stretch has a
// free run longer than `max_gap` (m) along the line midway between the two walls: no wall
// separates them there, wider than a door. With `max_share` < 1, a run longer than max_share of
// the common stretch and at least `min_run` (m) counts too (a narrow corridor cut across). False
// without a map. Symmetric.
bool open_join(const Scene& s, const Unit& a, const Unit& b, double dilate, double max_gap, double max_share,
               double min_run);
// Two units with connecting walls (as geom.adjacent with `dilate`) where a's wall is its shorter
// side: b lies off a's end, as the next piece of a corridor does. Not symmetric.
bool end_join(const Scene& s, const Unit& a, const Unit& b, double dilate);
}  // namespace geom

// ---- functions and term priors -----------------------------------------------------------
// |length difference| in metres of the connecting walls of two units (found with the default
// dilation of geom.adjacent, 2 cells); 0 when they have none. Symmetric.
double wall_length_diff(const Scene& s, const Unit& a, const Unit& b);
// Log density (up to its constant) of a zero-mean Gaussian: -x^2 / (2 sigma^2).
double gaussian(const Scene& s, double x, double sigma);

// ---- global priors (the weak prior of seed §3.6) ------------------------------------------------
struct RectPenalty {
  double psi1 = 1.0;  // log prior -= psi1 per misaligned adjacent wall pair
  double tol = 0.0;   // radians
  bool operator==(const RectPenalty&) const = default;
};
struct OverlapPenalty {
  double psi2 = 1.0;  // log prior -= psi2 per overlapping cell
  bool operator==(const OverlapPenalty&) const = default;
};
// `prior mln`: log Z(evidence of W) - log Z(no evidence atom holds), the Markov logic score
// of the world's evidence (a violated hard rule makes W impossible).
struct MlnPrior {
  bool operator==(const MlnPrior&) const = default;
};
using Prior = std::variant<RectPenalty, OverlapPenalty, MlnPrior>;
Prior rect_penalty(double psi1, double tol);
Prior overlap_penalty(double psi2);
Prior mln();

// ---- likelihood ----------------------------------------------------------------------------------
namespace grid {
// Tables lut[w][m] = p(map class m | world class w), classes 0 occupied, 1 unknown, 2 free (3 x 3).
// Units whose type (the most probable member of the exactly-one-of group) is a predicate of
// `lenient_types` use `lenient_lut`.
struct Occupancy {
  std::vector<std::vector<double>> lut;
  std::vector<std::int32_t> lenient_types;  // predicate ids
  std::vector<std::vector<double>> lenient_lut;
};
Occupancy occupancy(std::vector<std::vector<double>> lut, std::vector<std::int32_t> lenient_types,
                    std::vector<std::vector<double>> lenient_lut);
}  // namespace grid
using Likelihood = grid::Occupancy;

// ---- proposal sources ----------------------------------------------------------------------------
namespace detect {
struct Wbu {  // wall-based unit candidates (birth / death)
  double min_size = 1.5;  // m
  int max_units = 200;
  bool operator==(const Wbu&) const = default;
};
struct Fsu {  // free-space unit candidates, from proposal `after` on (birth / death)
  std::int64_t after = 4000;
  int min_area_cells = 100;
  bool operator==(const Fsu&) const = default;
};
struct Rpb {  // the robot-position unit candidate, with --robot (birth / death)
  double min_size = 1.0;  // m
  bool operator==(const Rpb&) const = default;
};
struct SplitLines {  // Hough split lines of a unit (split / merge)
  int min_votes = 20;
  double angle_tol = 0.0;  // radians
  bool operator==(const SplitLines&) const = default;
};
struct Doors {  // door candidates on connecting walls (allocate / deallocate)
  double min_width = 0.6, max_width = 2.0;  // m
  bool operator==(const Doors&) const = default;
};
}  // namespace detect
namespace partner {
struct InverseDistance {  // partner choice of merge and interchange
  bool operator==(const InverseDistance&) const = default;
};
}  // namespace partner
namespace move {
struct WallShift {  // Gaussian wall shift (shrink / dilate)
  double sigma = 2.0;  // cells
  bool operator==(const WallShift&) const = default;
};
struct Interchange {  // shared-wall shift or junction swap of two units (interchange)
  bool operator==(const Interchange&) const = default;
};
struct UniformRect {  // a share of births drawn uniformly over all rectangles (birth / death)
  double share = 0.005;
  bool operator==(const UniformRect&) const = default;
};
struct SeamDoors {  // doors on a split's cut allocated with it, deleted by the merge (split / merge)
  double min_width = 0.6, max_width = 2.0;  // m
  double max_cut = 3.0;    // m: only cuts across a corridor (blocks::cut_across_corridor)
  double min_ratio = 3.0;  // the two halves' length across the cut over the cut's length
  bool operator==(const SeamDoors&) const = default;
};
}  // namespace move
using Source = std::variant<detect::Wbu, detect::Fsu, detect::Rpb, detect::SplitLines, detect::Doors,
                            partner::InverseDistance, move::WallShift, move::Interchange, move::UniformRect,
                            move::SeamDoors>;

namespace detect {
Source wbu(double min_size, int max_units);
Source fsu(std::int64_t after, int min_area_cells);
Source rpb(double min_size);
Source split_lines(int min_votes, double angle_tol);
Source doors(double min_width, double max_width);
}  // namespace detect
namespace partner {
Source inverse_distance();
}  // namespace partner
namespace move {
Source wall_shift(double sigma);
Source interchange();
Source uniform_rect(double share);
Source seam_doors(double min_width, double max_width, double max_cut, double min_ratio);
}  // namespace move

// ---- outputs ---------------------------------------------------------------------------------------
struct Output {};  // the indoor kit declares no `extern output`

using Binding = runtime::domain::Binding<Scene, Prior, Likelihood, Move, Source, Output>;
using KernelDecl = runtime::domain::KernelDecl<Move, Source>;

}  // namespace ksmc::stdlib::indoor::blocks
