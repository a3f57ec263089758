#include "stdlib/indoor/map_evidence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ksmc::stdlib::indoor {

MapEvidence::MapEvidence(const ClassGrid& observed, int wall_probe)
    : observed_(observed.clone()), probe_(wall_probe) {
  if (observed_.empty()) throw std::invalid_argument("MapEvidence: empty class grid");
  if (wall_probe < 0) throw std::invalid_argument("MapEvidence: wall_probe must be >= 0");
}

Cell MapEvidence::cell_at(Point2 p) const {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return Cell::Unknown;
  const double c = std::floor(p.x + 0.5), r = std::floor(p.y + 0.5);
  if (c < 0 || r < 0 || c >= observed_.cols || r >= observed_.rows) return Cell::Unknown;
  return static_cast<Cell>(observed_(static_cast<int>(r), static_cast<int>(c)));
}

double MapEvidence::wall_weight(Point2 a, Point2 b) const {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (!(len > 0.0) || !std::isfinite(len)) return 0.0;
  const double nx = -dy / len, ny = dx / len;
  const int n = std::max(1, static_cast<int>(std::min(std::ceil(len), 1e7)));
  int hits = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const Point2 p{a.x + t * dx, a.y + t * dy};
    for (int k = -probe_; k <= probe_; ++k) {
      if (cell_at({p.x + k * nx, p.y + k * ny}) == Cell::Occupied) {
        ++hits;
        break;
      }
    }
  }
  return static_cast<double>(hits) / n;
}

std::array<double, 4> MapEvidence::wall_weights(const OrientedRect& r) const {
  const auto c = r.corners();
  std::array<double, 4> w{};
  for (std::size_t j = 0; j < 4; ++j) w[j] = wall_weight(c[j], c[(j + 1) % 4]);
  return w;
}

double MapEvidence::door_weight(Point2 a, Point2 b) const {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  if (!(len > 0.0) || !std::isfinite(len)) return 0.0;
  const int n = std::max(1, static_cast<int>(std::min(std::ceil(len), 1e7)));
  int hits = 0;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    hits += cell_at({a.x + t * dx, a.y + t * dy}) == Cell::Free ? 1 : 0;
  }
  return static_cast<double>(hits) / n;
}

Unit MapEvidence::make_unit(UnitId id, const OrientedRect& r, std::uint8_t lut_class) const {
  Unit u;
  u.id = id;
  u.rect = r;
  u.lut_class = lut_class;
  u.wall_weight = wall_weights(r);
  return u;
}

Door MapEvidence::make_door(DoorId id, UnitId a, UnitId b, Point2 pa, Point2 pb) const {
  Door d;
  d.id = id;
  d.unit_a = std::min(a, b);
  d.unit_b = std::max(a, b);
  d.a = pa;
  d.b = pb;
  d.weight = door_weight(pa, pb);
  return d;
}

}  // namespace ksmc::stdlib::indoor
