// The block functions and factories of stdlib/indoor/blocks.h.
#include "stdlib/indoor/blocks.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stdlib/indoor/blocks/walls.h"
#include "stdlib/indoor/free_distance.h"

namespace ksmc::stdlib::indoor::blocks {

namespace {
// Symmetric pair geometry: always measured from the unit with the lower id.
std::pair<const Unit*, const Unit*> ordered(const Unit& a, const Unit& b) {
  return a.id <= b.id ? std::pair{&a, &b} : std::pair{&b, &a};
}

// Calls f(x, y) (cells) at the centres of an nu x nv grid over the rectangle, in its own frame,
// until f returns true; says whether it did.
template <class F>
bool any_sample(const OrientedRect& r, int nu, int nv, F&& f) {
  const double c = std::cos(r.theta), sn = std::sin(r.theta);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double lx = ((i + 0.5) / nu - 0.5) * r.w, ly = ((j + 0.5) / nv - 0.5) * r.h;
      if (f(r.cx + c * lx - sn * ly, r.cy + sn * lx + c * ly)) return true;
    }
  return false;
}
}  // namespace

namespace geom {

bool room_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio, corridor_width) == GeomClass::RoomLike;
}
bool corridor_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio, corridor_width) == GeomClass::CorridorLike;
}
bool hall_like(const Scene& s, const Unit& u, double big_size, double big_ratio, double corridor_width) {
  return classify_unit(u.rect, s.resolution(), big_size, big_ratio, corridor_width) == GeomClass::HallLike;
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

bool thin(const Scene& s, const Unit& u, double min_width) {
  return std::min(std::abs(u.rect.w), std::abs(u.rect.h)) * s.resolution() < min_width;
}

bool blocked(const Scene& s, const Unit& u, double max_fraction) {
  const ClassGrid* map = s.map();
  if (map == nullptr) return false;
  const OrientedRect& r = u.rect;
  const int nu = std::clamp(static_cast<int>(std::abs(r.w)), 1, 24), nv = std::clamp(static_cast<int>(std::abs(r.h)), 1, 24);
  int total = 0, not_free = 0;
  any_sample(r, nu, nv, [&](double x, double y) {
    const int col = static_cast<int>(std::floor(x)), row = static_cast<int>(std::floor(y));
    ++total;
    if (row < 0 || col < 0 || row >= map->rows || col >= map->cols || (*map)(row, col) != static_cast<std::uint8_t>(Cell::Free))
      ++not_free;
    return false;
  });
  return not_free > max_fraction * total;
}

bool hollow(const Scene& s, const Unit& u, double min_width) {
  const cv::Mat1f* field = s.free_distance();
  if (field == nullptr || field->empty()) return false;
  const double reach = 0.5 * min_width / s.resolution();  // cells
  const double step = std::max(1.0, 0.5 * reach);
  const OrientedRect& r = u.rect;
  const int nu = std::max(1, static_cast<int>(std::ceil(std::abs(r.w) / step)));
  const int nv = std::max(1, static_cast<int>(std::ceil(std::abs(r.h) / step)));
  return any_sample(r, nu, nv, [&](double x, double y) { return free_distance_at(*field, x, y) > reach; });
}

bool open_join(const Scene& s, const Unit& a, const Unit& b, double dilate, double max_gap, double max_share,
               double min_run) {
  const ClassGrid* map = s.map();
  if (map == nullptr || a.id == b.id) return false;
  const auto [p, q] = ordered(a, b);
  const auto w = connecting_walls(p->rect, q->rect, dilate);
  if (!w) return false;
  const auto cp = p->rect.corners(), cq = q->rect.corners();
  const Point2 p0 = cp[static_cast<std::size_t>(w->wall_a)], p1 = cp[static_cast<std::size_t>((w->wall_a + 1) % 4)];
  const Point2 q0 = cq[static_cast<std::size_t>(w->wall_b)], q1 = cq[static_cast<std::size_t>((w->wall_b + 1) % 4)];
  const double la = std::hypot(p1.x - p0.x, p1.y - p0.y);
  const double dx = (p1.x - p0.x) / la, dy = (p1.y - p0.y) / la;
  // The stretch of wall a that wall b overlaps, moved to the midline between the walls.
  const double t0 = dx * (q0.x - p0.x) + dy * (q0.y - p0.y), t1 = dx * (q1.x - p0.x) + dy * (q1.y - p0.y);
  const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(la, std::max(t0, t1));
  const double off = 0.5 * (dx * (q0.y - p0.y) - dy * (q0.x - p0.x));  // signed half distance across
  const double nx = -dy, ny = dx;
  const double need = max_gap / s.resolution();
  // A run over `max_share` of the stretch is open too when it is at least `min_run` long: a
  // corridor narrower than max_gap, cut across, never has a run over max_gap.
  const double need_share = std::max(max_share * (hi - lo), min_run / s.resolution() - 1e-9);
  double run = 0.0;
  for (double t = lo + 0.5; t < hi; t += 1.0) {
    const int col = static_cast<int>(std::floor(p0.x + dx * t + nx * off));
    const int row = static_cast<int>(std::floor(p0.y + dy * t + ny * off));
    const bool free = row >= 0 && col >= 0 && row < map->rows && col < map->cols &&
                      (*map)(row, col) == static_cast<std::uint8_t>(Cell::Free);
    run = free ? run + 1.0 : 0.0;
    if (run > need || (max_share < 1.0 && run > need_share)) return true;
  }
  return false;
}

bool end_join(const Scene&, const Unit& a, const Unit& b, double dilate) {
  if (a.id == b.id) return false;
  const auto [p, q] = ordered(a, b);
  const auto w = connecting_walls(p->rect, q->rect, dilate);
  if (!w) return false;
  // a's wall is its shorter side when the side away from it is longer.
  const int wall = p == &a ? w->wall_a : w->wall_b;
  return edge_length(a.rect, wall) < depth_from_edge(a.rect, wall);
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
Prior mln() { return MlnPrior{}; }

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
Source move::uniform_rect(double share) { return UniformRect{share}; }
Source move::seam_doors(double min_width, double max_width, double max_cut, double min_ratio) {
  return SeamDoors{min_width, max_width, max_cut, min_ratio};
}

}  // namespace ksmc::stdlib::indoor::blocks
