#include "stdlib/indoor/io/unit_chains.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>

namespace ksmc::stdlib::indoor::io {

namespace {

struct Side {
  Point2 a, b;     // end points
  double tx, ty;   // unit direction a -> b
  double nx, ny;   // unit outward normal
  double length;
};

// The four sides of a finite, non-degenerate quad with outward normals; false otherwise.
bool sides_of(const Quad& q, std::array<Side, 4>& out) {
  if (!finite_quad(q)) return false;
  double cx = 0.0, cy = 0.0;
  for (const auto& p : q) cx += p.x / 4.0, cy += p.y / 4.0;
  for (std::size_t k = 0; k < 4; ++k) {
    Side s{q[k], q[(k + 1) % 4], 0, 0, 0, 0, 0};
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    s.length = std::hypot(dx, dy);
    if (!(s.length > 0.0)) return false;
    s.tx = dx / s.length, s.ty = dy / s.length;
    s.nx = s.ty, s.ny = -s.tx;
    if (s.nx * ((s.a.x + s.b.x) / 2 - cx) + s.ny * ((s.a.y + s.b.y) / 2 - cy) < 0.0) s.nx = -s.nx, s.ny = -s.ny;
    out[k] = s;
  }
  return true;
}

// Whether sides s and t face each other and meet (see SideMatch); the match when they do.
bool meet(const Side& s, const Side& t, double gap, SideMatch& m) {
  const double min_cos = std::cos(kSideAngleDeg * std::numbers::pi / 180.0);
  if (s.nx * t.nx + s.ny * t.ny > -min_cos) return false;
  const double apart = (t.a.x - s.a.x) * s.nx + (t.a.y - s.a.y) * s.ny;
  if (std::abs(apart) > gap) return false;
  const auto along = [&s](Point2 p) { return (p.x - s.a.x) * s.tx + (p.y - s.a.y) * s.ty; };
  const double t0 = std::min(along(t.a), along(t.b)), t1 = std::max(along(t.a), along(t.b));
  const double u0 = std::max(0.0, t0), u1 = std::min(s.length, t1);
  if (u1 - u0 < kSideOverlap * std::min(s.length, t.length)) return false;
  const double v0 = std::min(0.0, t0), v1 = std::max(s.length, t1);
  const auto at = [&](double u) { return Point2{s.a.x + u * s.tx + 0.5 * apart * s.nx, s.a.y + u * s.ty + 0.5 * apart * s.ny}; };
  m.from = at(v0), m.to = at(v1), m.lo = u0 - v0, m.hi = u1 - v0;
  return true;
}

}  // namespace

std::vector<SideMatch> matching_sides(const std::vector<UnitResult>& units, double gap) {
  std::vector<std::pair<int, std::array<Side, 4>>> sides;
  for (const auto& u : units) {
    std::array<Side, 4> s;
    if (sides_of(u.corners, s)) sides.emplace_back(u.id, s);
  }
  std::vector<SideMatch> out;
  for (std::size_t i = 0; i < sides.size(); ++i)
    for (std::size_t j = i + 1; j < sides.size(); ++j)
      for (const auto& s : sides[i].second)
        for (const auto& t : sides[j].second)
          if (SideMatch m; meet(s, t, gap, m)) {
            std::tie(m.a, m.b) = std::minmax(sides[i].first, sides[j].first);
            out.push_back(m);
          }
  std::sort(out.begin(), out.end(), [](const SideMatch& x, const SideMatch& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.hi - x.lo > y.hi - y.lo;
  });
  out.erase(std::unique(out.begin(), out.end(), [](const SideMatch& x, const SideMatch& y) { return x.a == y.a && x.b == y.b; }),
            out.end());
  return out;
}

std::vector<std::pair<int, int>> continued_units(const ClassGrid& grid, const std::vector<UnitResult>& units) {
  std::vector<std::pair<int, int>> out;
  for (const SideMatch& m : matching_sides(units, kSeamGap)) {
    const double len = std::hypot(m.to.x - m.from.x, m.to.y - m.from.y);
    if (!(len > 0.0)) continue;
    const double tx = (m.to.x - m.from.x) / len, ty = (m.to.y - m.from.y) / len;
    const auto free_cell = [&grid](double x, double y) {
      const int r = static_cast<int>(std::lround(y)), c = static_cast<int>(std::lround(x));
      return r >= 0 && c >= 0 && r < grid.rows && c < grid.cols && grid(r, c) == static_cast<std::uint8_t>(Cell::Free);
    };
    // Free samples along the seam shifted by `off` cells across it, one per cell; a sample is
    // free when the cells 1 cell either side of it across the seam are too (a wall drawn one cell
    // thin, slanted against the units' frame, is not missed). `shared`: of them, those where
    // both sides are.
    struct Count {
      int free = 0, shared = 0;
    };
    const int samples = static_cast<int>(std::floor(len)) + 1;
    const auto count_along = [&](double off) {
      Count n;
      for (int i = 0; i < samples; ++i) {
        const double t = i;
        bool open = true;
        for (const double k : {off - 1.0, off, off + 1.0})
          open = open && free_cell(m.from.x + t * tx - k * ty, m.from.y + t * ty + k * tx);
        if (open) {
          ++n.free;
          n.shared += t >= m.lo - 0.5 && t <= m.hi + 0.5;
        }
      }
      return n;
    };
    const int beside = std::max(count_along(-kSeamBeside).free, count_along(kSeamBeside).free);
    const Count seam = count_along(0.0);
    if (beside >= kFreeBeside * samples && seam.free >= kOpenSeam * beside && seam.shared >= kSharedSeam * seam.free)
      out.emplace_back(m.a, m.b);
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
