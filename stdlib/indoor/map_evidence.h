// How well world members match the classified map: wall weight omega_w (eq. 3.11-3.14),
// unit weight omega_r (eq. 3.10), door weight omega_g (eq. 3.23-3.25). Walls are sampled at
// one point per cell of length; a sample counts as matched when a cell within `wall_probe`
// cells across the wall is Occupied (the seed's t(x,y) with the wall's own cells widened by the
// probe, since unit edges lie on wall centre lines only up to a cell). A door sample counts
// when the cell under it is Free.
#pragma once

#include <array>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

class MapEvidence {
 public:
  explicit MapEvidence(const ClassGrid& observed, int wall_probe = 1);

  const ClassGrid& observed() const { return observed_; }
  // Class of the cell whose centre is nearest to p; Unknown outside the map.
  Cell cell_at(Point2 p) const;

  double wall_weight(Point2 a, Point2 b) const;
  std::array<double, 4> wall_weights(const OrientedRect& r) const;
  double door_weight(Point2 a, Point2 b) const;

  // A unit / door with its weights filled in.
  Unit make_unit(UnitId id, const OrientedRect& r, std::uint8_t lut_class = 0) const;
  Door make_door(DoorId id, UnitId a, UnitId b, Point2 pa, Point2 pb) const;

 private:
  ClassGrid observed_;
  int probe_;
};

}  // namespace ksmc::stdlib::indoor
