#include "stdlib/tabletop/perception/stack_split.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "stdlib/tabletop/perception/footprint.h"
#include "stdlib/tabletop/perception/ray_meeting.h"
#include "stdlib/tabletop/perception/top_parts.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

// Heights of the plateaus (top surfaces), highest first: histogram of cell maxima in
// level_gap / 4 bins, a level is a peak: three neighbouring bins holding min_level_area
// and peak_contrast times the four bins around them (or, next to another top's plateau, twice
// the two on one side with a valley toward the other: StackOptions::valley_share); a level
// closer than level_gap to the one above only with a valley between. The first window from the top that
// qualifies can be centred a bin above the top itself (noise spills the top's maxima into the
// bin above), so a level's height is then measured, not binned: the median height of the
// points near it (within two bins) in cells whose maximum is near it too, i.e. the top face's
// points, not its cells' maxima (the maximum of a few noisy points lies above the face).
std::vector<double> plateaus(const Points& points, const StackOptions& o) {
  const auto cell_of = [&o](const Eigen::Vector3d& p) {
    return std::make_pair(std::lround(std::floor(p.x() / o.cell)), std::lround(std::floor(p.y() / o.cell)));
  };
  std::map<std::pair<long, long>, double> top;
  for (const auto& p : points) {
    auto [it, fresh] = top.emplace(cell_of(p), p.z());
    if (!fresh) it->second = std::max(it->second, p.z());
  }
  const double bin = 0.25 * o.level_gap;
  std::map<long, int> hist;
  for (const auto& [k, h] : top) ++hist[std::lround(std::floor(h / bin))];
  const int need = static_cast<int>(std::ceil(o.min_level_area / (o.cell * o.cell)));
  std::vector<double> levels, binned;  // measured heights; the peaks' bin centres
  for (auto it = hist.rbegin(); it != hist.rend(); ++it) {
    auto at = [&](long k) {
      const auto f = hist.find(k);
      return f == hist.end() ? 0 : f->second;
    };
    const long k = it->first;
    const int count = at(k - 1) + at(k) + at(k + 1);
    const int below = at(k - 3) + at(k - 2), above = at(k + 2) + at(k + 3);
    const double h = (static_cast<double>(k) + 0.5) * bin;
    const bool valleys = o.valley_share >= 0.0;
    const auto empty_ish = [&](long j, int of) { return at(j) <= o.valley_share * of; };
    // A flat top is a peak; a tilted face spreads evenly over the bins (count/flank = 3/4).
    // Next to another top, one side is clean and a valley lies toward the other.
    const bool peak =
        count >= o.peak_contrast * (below + above) ||
        (valleys && count >= 2.0 * o.peak_contrast * above && (empty_ish(k - 1, at(k)) || empty_ish(k - 2, at(k)))) ||
        (valleys && count >= 2.0 * o.peak_contrast * below && (empty_ish(k + 1, at(k)) || empty_ish(k + 2, at(k))));
    if (count < need || !peak) continue;
    if (!levels.empty() && binned.back() - h < o.level_gap) {
      const long upper = std::lround(std::floor(binned.back() / bin));
      if (!valleys || upper - k < o.min_valley_bins) continue;
      bool valley = true;
      for (long j = k + 1; j < upper; ++j) valley = valley && empty_ish(j, std::min(at(k), at(upper)));
      if (!valley) continue;
    }
    binned.push_back(h);
    const double lo = (static_cast<double>(k) - 2.0) * bin, hi = (static_cast<double>(k) + 2.0) * bin;
    std::vector<double> near;
    for (const auto& p : points) {
      if (p.z() < lo || p.z() >= hi) continue;
      const double cell_top = top.at(cell_of(p));
      if (cell_top >= lo && cell_top < hi) near.push_back(p.z());
    }
    // `near` holds at least the points whose cells made the peak, so it is not empty.
    const auto mid = near.begin() + static_cast<std::ptrdiff_t>(near.size() / 2);
    std::nth_element(near.begin(), mid, near.end());
    levels.push_back(*mid);
  }
  return levels;
}

bool inside(const Rect2& r, const Eigen::Vector2d& p, double margin) {
  const Eigen::Vector2d d = p - r.center;
  return std::abs(d.dot(r.u)) <= r.half.x() + margin && std::abs(d.dot(r.v())) <= r.half.y() + margin;
}

// Share of rectangle a's area covered by rectangle b (sampled on a 20 x 20 grid).
double covered(const Rect2& a, const Rect2& b) {
  int in = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const Eigen::Vector2d p = a.center + ((i + 0.5) / 10.0 - 1.0) * a.half.x() * a.u + ((j + 0.5) / 10.0 - 1.0) * a.half.y() * a.v();
      in += inside(b, p, 0.0);
    }
  return in / 400.0;
}

// The column under the plateau, inset by `seen_inset` on every side, as a box; none when the
// inset leaves nothing.
std::optional<Obb> column_below(const Rect2& column, double below, const StackOptions& o) {
  if (below <= 2.0 * o.seen_inset || column.half.x() <= o.seen_inset || column.half.y() <= o.seen_inset) return std::nullopt;
  return upright_over(column, 0.0, below, o.seen_inset);
}

// True when the sensor saw through where the upper box's column would stand below the
// lower plateau: rays ended behind that space, so no box stands there.
bool seen_through_below(const Rect2& column, double below, std::size_t upper_points, const StackOptions& o,
                        const RayIndex& rays) {
  const std::optional<Obb> under = column_below(column, below, o);
  if (!under) return false;
  const double limit = std::max(static_cast<double>(o.min_seen_through), o.seen_through_share * static_cast<double>(upper_points));
  return static_cast<double>(rays.see_through_count(*under)) > limit;
}

// Of the rays toward the column under the plateau that end before reaching it, true when at
// least as many end on the column's own top part (above the plateau, within the column) as on
// something outside the column: that space lies in the top's own shadow, not behind a box in
// front, which would hide a box's lower faces standing on the table.
bool in_own_shadow(const Rect2& column, double below, const StackOptions& o, const RayIndex& rays) {
  const std::optional<Obb> under = column_below(column, below, o);
  if (!under) return false;
  const FreeSpace& seen = rays.free_space();
  std::size_t own = 0, front = 0;
  for_each_meeting(*under, {}, rays, seen.margin, [&](std::size_t ray, RayMeets how) {
    if (how != RayMeets::before) return;  // reaches the space (or passes it)
    const Eigen::Vector3d& p = seen.points[ray];
    if (!inside(column, {p.x(), p.y()}, o.column_margin)) ++front;
    else if (p.z() > below + 0.5 * o.level_gap) ++own;
  });
  return own > 0 && own >= front;
}

// True when the column's side faces stop at the plateau: under it the column holds fewer than
// `max_points_below` points and fewer than `max_below_share` of what its side faces above the
// plateau (below the top's last centimetre) would put there at the same density per height.
bool faces_stop_at(const Points& whole, const Points& top_part, double below, const StackOptions& o) {
  double top = below;
  for (const auto& p : top_part) top = std::max(top, p.z());
  const double lower = below - 0.5 * o.level_gap, upper = below + 0.5 * o.level_gap;
  std::size_t under = 0, side = 0;
  for (const auto& p : whole) {
    under += p.z() < lower;
    side += p.z() > upper && p.z() < top - o.top_band;
  }
  const double expected = static_cast<double>(side) * lower / std::max(top - o.top_band - upper, o.cell);
  return under < o.max_points_below && static_cast<double>(under) < o.max_below_share * expected;
}

// True when the column's side faces step at the plateau below (side_steps.h): its faces
// under that height are another box's, so it rests there.
bool steps_at(const Points& column, double below, const StackOptions& o) {
  for (const SideStep& s : side_steps(column, 0.0, o.sides))
    if (std::abs(s.z - below) <= 0.5 * o.level_gap) return true;
  return false;
}

std::vector<Eigen::Vector2d> flat(const Points& pts) {
  std::vector<Eigen::Vector2d> f;
  for (const auto& p : pts) f.emplace_back(p.x(), p.y());
  return f;
}

}  // namespace

std::vector<UprightBox> fit_stacked_boxes(const Points& points, const BoxFitOptions& box, const StackOptions& o,
                                          const RayIndex* rays) {
  std::vector<std::vector<UprightBox>> upper;  // found from the top down, each lowest first
  Points rest = points;
  // The lower boxes' side faces under a resting upper box. They are kept out of the plateau
  // search (the upper box's shadow line along such a face reads as a level of its own) and
  // join the fit of the box whose height range they fall in.
  Points sides;
  while (static_cast<int>(upper.size()) + 1 < o.max_boxes) {
    const std::vector<double> levels = plateaus(rest, o);
    if (levels.size() < 2) break;
    const double below = levels[1];
    Points top;
    for (const auto& p : rest)
      if (p.z() > below + 0.5 * o.level_gap) top.push_back(p);
    if (top.size() < o.min_points) break;
    // Tops with a lower surface seen between them are different boxes (top_parts.h).
    const std::vector<Points> parts =
        o.separate_tops ? top_parts(top, rest, below + 0.5 * o.level_gap, {o.cell, o.min_lower_cells, o.min_points})
                        : std::vector<Points>{top};
    std::vector<Rect2> columns;
    for (const Points& part : parts) columns.push_back(min_area_rect(flat(part), box.footprint_trim));
    const auto column_of = [&columns](const Eigen::Vector3d& p, double margin) {
      for (std::size_t k = 0; k < columns.size(); ++k)
        if (inside(columns[k], {p.x(), p.y()}, margin)) return static_cast<int>(k);
      return -1;
    };
    Points remaining;
    for (const auto& p : rest)
      if (p.z() <= below + 0.5 * o.level_gap && column_of(p, o.column_margin) < 0) remaining.push_back(p);
    if (remaining.size() < o.min_points) break;
    const Rect2 under = min_area_rect(flat(remaining), box.footprint_trim);
    // The sides above the plateau go with the column they stand in (else the nearest); those
    // lower than its bottom, for the boxes under it (the band around the plateau is left out, as
    // the rest's points are).
    std::vector<Points> part_sides(parts.size());
    Points below_sides;
    for (const auto& p : sides) {
      if (p.z() > below + 0.5 * o.level_gap) {
        int k = column_of(p, o.column_margin);
        if (k < 0) {
          k = 0;
          for (std::size_t j = 1; j < columns.size(); ++j)
            if ((columns[j].center - p.head<2>()).squaredNorm() < (columns[static_cast<std::size_t>(k)].center - p.head<2>()).squaredNorm())
              k = static_cast<int>(j);
        }
        part_sides[static_cast<std::size_t>(k)].push_back(p);
      } else if (p.z() <= below - 0.5 * o.level_gap) {
        below_sides.push_back(p);
      }
    }
    std::vector<UprightBox> column_boxes;
    Points next_sides = std::move(below_sides);
    bool any_rests = false;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const Rect2& column = columns[k];
      Points whole, reach;  // the column down to the table; and with the faces a side step may reach
      for (const auto& p : rest) {
        if (inside(column, {p.x(), p.y()}, o.column_margin)) whole.push_back(p);
        if (inside(column, {p.x(), p.y()}, o.sides.max_offset)) reach.push_back(p);
      }
      std::vector<UprightBox> fitted;
      if (covered(column, under) >= o.min_support ||
          (o.centre_inset >= 0.0 && inside(under, column.center, -o.centre_inset)) ||
          (o.free_space && rays != nullptr && seen_through_below(column, below, parts[k].size(), o, *rays)) ||
          steps_at(reach, below, o) ||
          (rays != nullptr && faces_stop_at(whole, parts[k], below, o) && in_own_shadow(column, below, o, *rays))) {  // resting on the rest: bottom at the plateau below
        any_rests = true;
        Points part = parts[k];
        part.insert(part.end(), part_sides[k].begin(), part_sides[k].end());
        fitted = fit_column(part, below, box, o.sides);
        if (o.lower_sides)
          for (const auto& p : rest)
            if (p.z() <= below - 0.5 * o.level_gap && inside(column, {p.x(), p.y()}, o.column_margin)) next_sides.push_back(p);
      } else {  // a merged neighbour standing on the table: its column goes down to the table
        fitted = fit_column(whole, 0.0, box, o.sides);
        next_sides.insert(next_sides.end(), part_sides[k].begin(), part_sides[k].end());
      }
      column_boxes.insert(column_boxes.end(), fitted.begin(), fitted.end());
    }
    // With no box resting on the rest, the sides are kept as they were (none was used).
    if (any_rests) sides = std::move(next_sides);
    upper.push_back(std::move(column_boxes));
    rest = std::move(remaining);
  }
  rest.insert(rest.end(), sides.begin(), sides.end());
  std::vector<UprightBox> out = fit_column(rest, 0.0, box, o.sides);
  for (auto it = upper.rbegin(); it != upper.rend(); ++it) out.insert(out.end(), it->begin(), it->end());
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
