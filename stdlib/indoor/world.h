// The indoor world W (seed §3.4): rectangular units (walls are their edges) and doors joining
// two units on a shared wall. Units and doors carry stable ids (never reused) and are kept
// sorted by id, so iteration order is deterministic. A world changes only through Moves:
// deltas listing each unit/door before and after, which can be applied and inverted exactly.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "stdlib/indoor/rect.h"

namespace ksmc::stdlib::indoor {

using UnitId = std::uint32_t;
using DoorId = std::uint32_t;

// Number of per-type likelihood tables a cell can select from (LUT class 0 = default).
inline constexpr int kMaxLutClasses = 4;

struct Unit {
  UnitId id = 0;
  OrientedRect rect;
  // Index of the likelihood table used by the cells this unit covers (type-dependent sensor
  // model: e.g. 1 = lenient table for Room/Hall). 0 = default table.
  std::uint8_t lut_class = 0;
  // Wall weights omega_w (eq. 3.11) of the four walls, wall j = edge corner j -> corner j+1.
  // Filled by MapEvidence::make_unit; only the kernels read them.
  std::array<double, 4> wall_weight{0.0, 0.0, 0.0, 0.0};
  // Unit weight omega_r (eq. 3.10): the lowest wall weight.
  double weight() const;
};

struct Door {
  DoorId id = 0;
  UnitId unit_a = 0, unit_b = 0;  // unit_a < unit_b
  Point2 a, b;                     // the door segment on the shared wall
  double weight = 0.0;             // omega_g (eq. 3.23), filled by MapEvidence::make_door
};

// The kernel that produced a move (the reverse kernel is given by reverse_of()).
enum class KernelKind : std::uint8_t {
  Add, Remove, Split, Merge, Shrink, Dilate, Allocate, Delete, Interchange
};
inline constexpr int kKernelKinds = 9;
KernelKind reverse_of(KernelKind k);
// The move's name as stdlib/indoor.ksm declares it (`makes birth / death`, ...).
const char* kernel_name(KernelKind k);

struct UnitChange {
  UnitId id = 0;
  std::optional<Unit> before;  // absent: the unit is added
  std::optional<Unit> after;   // absent: the unit is removed
};

struct DoorChange {
  DoorId id = 0;
  std::optional<Door> before;
  std::optional<Door> after;
};

// Kernel-specific parameters of a move, enough for the reverse kernel to score its inverse.
struct MoveDetail {
  int wall = -1;       // SHRINK/DILATE: wall index of the changed unit
  double delta = 0.0;  // SHRINK/DILATE: outward shift; INTERCHANGE shift: growth of units[0]
  int variant = 0;     // INTERCHANGE: 0 = shift the shared wall, 1 = swap the junction
};

struct Move {
  KernelKind kind = KernelKind::Add;
  std::vector<UnitChange> units;
  std::vector<DoorChange> doors;
  MoveDetail detail;

  // The move that undoes this one (before/after swapped, kind reversed, delta negated).
  Move inverse() const;
};

class World {
 public:
  std::span<const Unit> units() const { return units_; }
  std::span<const Door> doors() const { return doors_; }
  const Unit* find_unit(UnitId id) const;
  const Door* find_door(DoorId id) const;
  // Number of doors attached to the unit.
  int door_count(UnitId id) const;

  // Ids a move created on this world should use for new members.
  UnitId next_unit_id() const { return next_unit_id_; }
  DoorId next_door_id() const { return next_door_id_; }

  // Applies a move; throws std::logic_error when the move does not fit this world (a member
  // to remove or change is missing, a member to add exists, a door refers to an absent unit).
  void apply(const Move& m);
  World applied(const Move& m) const;

 private:
  void apply_in_place(const Move& m);

  std::vector<Unit> units_;  // sorted by id
  std::vector<Door> doors_;  // sorted by id
  UnitId next_unit_id_ = 1;
  DoorId next_door_id_ = 1;
};

}  // namespace ksmc::stdlib::indoor
