#include "stdlib/indoor/kit/merged_units.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/kit/wall_lines.h"

namespace ksmc::stdlib::indoor::kit {

namespace {

// Whether boxes a and b lie side by side along x (their seam is a line x = const) rather than
// along y: the axis on which they are farther apart (or overlap less).
bool side_by_side_along_x(const Box& a, const Box& b) {
  return std::max(a.x0, b.x0) - std::min(a.x1, b.x1) >= std::max(a.y0, b.y0) - std::min(a.y1, b.y1);
}

// Share of the seam between boxes a and b (in frame f) that has an occupied cell within
// kMergeSeamReach across it; 0 when the boxes nest (no seam).
double seam_wall_share(const Box& a, const Box& b, const Frame& f, const ClassGrid& observed) {
  const bool across_x = side_by_side_along_x(a, b);
  // The seam's position and its extent along the other axis.
  const double at = across_x ? 0.5 * (std::max(a.x0, b.x0) + std::min(a.x1, b.x1))
                             : 0.5 * (std::max(a.y0, b.y0) + std::min(a.y1, b.y1));
  const double lo = across_x ? std::max(a.y0, b.y0) : std::max(a.x0, b.x0);
  const double hi = across_x ? std::min(a.y1, b.y1) : std::min(a.x1, b.x1);
  const double overlap = across_x ? std::min(a.x1, b.x1) - std::max(a.x0, b.x0) : std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  const double a_len = across_x ? a.x1 - a.x0 : a.y1 - a.y0, b_len = across_x ? b.x1 - b.x0 : b.y1 - b.y0;
  if (overlap >= 0.5 * std::min(a_len, b_len)) return 0.0;  // one lies over the other: no seam
  // The seam's ends lie in the walls the two units share at their sides (up to 0.3 m thick,
  // half of it inside): they are not counted.
  const double trim = std::max(1.0, kMergeSeamTrim * (hi - lo));
  return wall_share(wall_samples(observed, FrameLine{&f, across_x, at, lo + trim, hi - trim}, kMergeSeamReach));
}

}  // namespace

std::vector<MergeCandidate> merge_candidates(const World& w, const ClassGrid& observed) {
  std::vector<MergeCandidate> out;
  const auto units = w.units();
  for (const Unit& ua : units)
    for (const Unit& ub : units) {
      if (!(ua.id < ub.id)) continue;
      const Frame f(ua.rect.theta);
      const Box a = own_box(ua.rect);
      const auto b = box_in_frame(ub.rect, f, kMergeAngleDeg * kPi / 180.0);
      if (!b) continue;
      const Box u{std::min(a.x0, b->x0), std::max(a.x1, b->x1), std::min(a.y0, b->y0), std::max(a.y1, b->y1)};
      const double inter = std::max(0.0, std::min(a.x1, b->x1) - std::max(a.x0, b->x0)) *
                           std::max(0.0, std::min(a.y1, b->y1) - std::max(a.y0, b->y0));
      const double area = u.width() * u.height();
      if (!(area > 0.0)) continue;
      const double fill = (a.width() * a.height() + b->width() * b->height() - inter) / area;
      if (fill < kMergeFill || seam_wall_share(a, *b, f, observed) > kMergeWallShare) continue;
      // Across the line they join along, the new rectangle spans both (the bounding one), their
      // common part, or one unit's extent: units one or two cells apart in width otherwise
      // leave a wall band off the wall. Side by side along x, the cross axis is y.
      const bool along_x = side_by_side_along_x(a, *b);
      auto cross = [&](const Box& x) { return along_x ? std::pair{x.y0, x.y1} : std::pair{x.x0, x.x1}; };
      const auto [a0, a1] = cross(a);
      const auto [b0, b1] = cross(*b);
      std::vector<std::pair<double, double>> spans{{std::min(a0, b0), std::max(a1, b1)}};
      for (const auto& sp : {std::pair{std::max(a0, b0), std::min(a1, b1)}, std::pair{a0, a1}, std::pair{b0, b1}})
        if (sp.second - sp.first > 0.0 &&
            std::none_of(spans.begin(), spans.end(), [&](const auto& t) {
              return std::abs(t.first - sp.first) < 1e-9 && std::abs(t.second - sp.second) < 1e-9;
            }))
          spans.push_back(sp);
      for (const auto& [lo, hi] : spans) {
        const Box v = along_x ? Box{u.x0, u.x1, lo, hi} : Box{lo, hi, u.y0, u.y1};
        const bool doors_fit = std::all_of(w.doors().begin(), w.doors().end(), [&](const Door& d) {
          const bool in_a = d.unit_a == ua.id || d.unit_b == ua.id, in_b = d.unit_a == ub.id || d.unit_b == ub.id;
          if (in_a == in_b) return true;  // joins the two (it goes), or neither
          const Point2 mid{0.5 * (d.a.x + d.b.x), 0.5 * (d.a.y + d.b.y)};
          return distance_to_boundary(v, f.to_local(mid)) <= kMergeDoorSnap;
        });
        if (doors_fit) out.push_back({ua.id, ub.id, rect_from_box(v, f), fill});
      }
    }
  std::stable_sort(out.begin(), out.end(), [](const MergeCandidate& x, const MergeCandidate& y) {
    if (x.fill != y.fill) return x.fill > y.fill;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return out;
}

Move merge_move(const World& w, const MapEvidence& ev, const MergeCandidate& c) {
  const Unit& ua = *w.find_unit(c.a);
  const Unit& ub = *w.find_unit(c.b);
  const UnitId id = w.next_unit_id();
  Move m;
  m.kind = KernelKind::Merge;
  m.units = {{ua.id, ua, std::nullopt}, {ub.id, ub, std::nullopt}, {id, std::nullopt, ev.make_unit(id, c.rect, ua.lut_class)}};
  auto in_pair = [&](UnitId u) { return u == c.a || u == c.b; };
  for (const Door& d : w.doors()) {
    const bool fa = in_pair(d.unit_a), fb = in_pair(d.unit_b);
    if (!fa && !fb) continue;
    if (fa && fb) {
      m.doors.push_back({d.id, d, std::nullopt});
      continue;
    }
    const UnitId other = fa ? d.unit_b : d.unit_a;
    m.doors.push_back({d.id, d, ev.make_door(d.id, std::min(id, other), std::max(id, other), d.a, d.b)});
  }
  return m;
}

}  // namespace ksmc::stdlib::indoor::kit
