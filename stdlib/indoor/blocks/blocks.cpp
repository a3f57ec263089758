// The block functions and factories of stdlib/indoor/blocks.h.
#include "stdlib/indoor/blocks.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stdlib/indoor/blocks/walls.h"

namespace ksmc::stdlib::indoor::blocks {

namespace {
// Symmetric pair geometry: always measured from the unit with the lower id.
std::pair<const Unit*, const Unit*> ordered(const Unit& a, const Unit& b) {
  return a.id <= b.id ? std::pair{&a, &b} : std::pair{&b, &a};
}
}  // namespace

namespace geom {

bool room_like(const Scene& s, const Unit& u, double big_size, double big_ratio) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio) == GeomClass::RoomLike;
}
bool corridor_like(const Scene& s, const Unit& u, double big_size, double big_ratio) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio) == GeomClass::CorridorLike;
}
bool hall_like(const Scene& s, const Unit& u, double big_size, double big_ratio) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio) == GeomClass::HallLike;
}

bool adjacent(const Scene&, const Unit& a, const Unit& b, double dilate) {
  if (a.id == b.id) return false;  // a unit is not adjacent to itself
  const auto [p, q] = ordered(a, b);
  return connecting_walls(p->rect, q->rect, dilate).has_value();
}

bool multi_door(const Scene&, const Unit& u, std::span<const Door> doors, int min_doors) {
  const auto n = std::count_if(doors.begin(), doors.end(), [&](const Door& d) { return d.unit_a == u.id || d.unit_b == u.id; });
  return n >= min_doors;
}

}  // namespace geom

double wall_length_diff(const Scene& s, const Unit& a, const Unit& b) {
  const auto [p, q] = ordered(a, b);
  const auto w = connecting_walls(p->rect, q->rect, kDefaultDilateCells);
  return w ? std::abs(w->length_a - w->length_b) * s.resolution() : 0.0;
}

double gaussian(const Scene&, double x, double sigma) { return -0.5 * (x / sigma) * (x / sigma); }

Prior rect_penalty(double psi1, double tol) { return RectPenalty{psi1, tol}; }
Prior overlap_penalty(double psi2) { return OverlapPenalty{psi2}; }

grid::Occupancy grid::occupancy(std::vector<std::vector<double>> lut, std::vector<std::int32_t> lenient_types,
                                std::vector<std::vector<double>> lenient_lut) {
  return {std::move(lut), std::move(lenient_types), std::move(lenient_lut)};
}

Source detect::wbu(double min_size, int max_units) { return Wbu{min_size, max_units}; }
Source detect::fsu(std::int64_t after, int min_area_cells) { return Fsu{after, min_area_cells}; }
Source detect::rpb(double min_size) { return Rpb{min_size}; }
Source detect::split_lines(int min_votes, double angle_tol) { return SplitLines{min_votes, angle_tol}; }
Source detect::doors(double min_width, double max_width) { return Doors{min_width, max_width}; }
Source partner::inverse_distance() { return InverseDistance{}; }
Source move::wall_shift(double sigma) { return WallShift{sigma}; }
Source move::interchange() { return Interchange{}; }

}  // namespace ksmc::stdlib::indoor::blocks
