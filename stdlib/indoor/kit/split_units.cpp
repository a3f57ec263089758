#include "stdlib/indoor/kit/split_units.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/kit/merged_units.h"
#include "stdlib/indoor/kit/wall_lines.h"

namespace ksmc::stdlib::indoor::kit {

namespace {

// The longest run of non-wall samples (half a cell apart, from t0): its ends, or nullopt.
std::optional<std::pair<double, double>> longest_opening(const std::vector<bool>& s, double t0) {
  std::size_t best_len = 0, best_at = 0;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < s.size() && !s[j]) ++j;
    if (j - i > best_len) best_len = j - i, best_at = i;
    i = j;
  }
  if (best_len == 0) return std::nullopt;
  return std::pair{t0 + 0.5 * static_cast<double>(best_at), t0 + 0.5 * static_cast<double>(best_at + best_len)};
}

// Whether a cut reads as a partition: thin wall (kSplitThinWall) for kSplitThinShare of it, and
// no opening wider than a door. A block of furniture the cut runs through or along is thick
// (measured on the independent plans: rooms cut beside desks and cupboards, unit precision
// 0.949 -> 0.937 without this test); a partition may be thick in places (a pillar, a black
// outside against it: lab_ipa).
bool partition(const std::vector<bool>& any, const std::vector<bool>& thin, double max_door) {
  if (wall_share(thin) < kSplitThinShare) return false;
  std::size_t run = 0;
  for (const bool x : any) {
    run = x ? 0 : run + 1;
    if (0.5 * static_cast<double>(run) > max_door) return false;
  }
  return true;
}

}  // namespace

std::vector<SplitCandidate> split_candidates(const Unit& u, const ClassGrid& observed, double min_door,
                                             double max_door) {
  std::vector<SplitCandidate> out;
  const Frame f(u.rect.theta);
  const Box b = own_box(u.rect);
  for (const bool across_x : {true, false}) {  // across_x: the cut is a line x = at
    const double a0 = across_x ? b.x0 : b.y0, a1 = across_x ? b.x1 : b.y1;
    const double lo = (across_x ? b.y0 : b.x0) + kSplitEndMargin, hi = (across_x ? b.y1 : b.x1) - kSplitEndMargin;
    if (hi - lo < 1.0) continue;
    // Per position: the share of the cut with a wall within kSplitReach when it is a partition,
    // and the share of the two cells the parts' wall bands would predict there that are
    // occupied (is the cut on it? the position is the peak of this one). Both are read only
    // where the first could reach kSplitWallShare.
    std::vector<double> at, share;
    std::vector<std::vector<bool>> samples;
    // Most lines cross open floor: their sampling stops at the first opening wider than max_door
    // or once more than half the line is not wall (either rejects the line). Every position
    // has as many samples.
    const std::size_t n = sample_count(FrameLine{&f, across_x, 0.0, lo, hi});
    const auto max_open = static_cast<std::size_t>(std::max(0.0, 2.0 * max_door));
    const auto max_missing = static_cast<std::size_t>(std::floor((1.0 - kSplitWallShare) * static_cast<double>(n)));
    for (double t = a0 + kSplitMinPart; t <= a1 - kSplitMinPart; t += 0.5) {
      const FrameLine line{&f, across_x, t, lo, hi};
      at.push_back(t);
      auto s = wall_samples_bounded(observed, line, kSplitReach, 0, max_open, max_missing);
      const double any = s ? wall_share(*s) : 0.0;
      share.push_back(s && any >= kSplitWallShare &&
                              partition(*s, wall_samples(observed, line, kSplitReach, kSplitThinWall), max_door)
                          ? any
                          : 0.0);
      samples.push_back(s ? std::move(*s) : std::vector<bool>{});
    }
    std::vector<double> hit(at.size(), -1.0);
    auto hit_at = [&](std::size_t i) {
      if (hit[i] < 0.0)
        hit[i] = 0.5 * (wall_share(wall_samples(observed, FrameLine{&f, across_x, at[i] - 0.5, lo, hi}, 0)) +
                        wall_share(wall_samples(observed, FrameLine{&f, across_x, at[i] + 0.5, lo, hi}, 0)));
      return hit[i];
    };
    for (std::size_t i = 0; i < at.size(); ++i) {
      if (share[i] < kSplitWallShare) continue;
      // A local maximum of `hit` over +-3 cells (the first of equal ones).
      bool peak = true;
      for (std::size_t j = i >= 6 ? i - 6 : 0; j < std::min(at.size(), i + 7) && peak; ++j)
        peak = !(hit_at(j) > hit_at(i) || (hit_at(j) == hit_at(i) && j < i));
      if (!peak) continue;
      SplitCandidate c;
      c.unit = u.id;
      c.share = share[i];
      const Box p = across_x ? Box{b.x0, at[i], b.y0, b.y1} : Box{b.x0, b.x1, b.y0, at[i]};
      const Box q = across_x ? Box{at[i], b.x1, b.y0, b.y1} : Box{b.x0, b.x1, at[i], b.y1};
      c.first = rect_from_box(p, f);
      c.second = rect_from_box(q, f);
      if (const auto o = longest_opening(samples[i], lo); o && o->second - o->first >= min_door &&
                                                           o->second - o->first <= max_door) {
        const FrameLine line{&f, across_x, at[i], lo, hi};
        c.door = std::pair{line.point(o->first), line.point(o->second)};
      }
      out.push_back(c);
    }
  }
  return out;
}

void sort_split_candidates(std::vector<SplitCandidate>& cs) {
  std::stable_sort(cs.begin(), cs.end(), [](const SplitCandidate& x, const SplitCandidate& y) { return x.share > y.share; });
}

std::vector<SplitCandidate> split_candidates(const World& w, const ClassGrid& observed, double min_door,
                                             double max_door) {
  std::vector<SplitCandidate> out;
  for (const Unit& u : w.units()) {
    const auto mine = split_candidates(u, observed, min_door, max_door);
    out.insert(out.end(), mine.begin(), mine.end());
  }
  sort_split_candidates(out);
  return out;
}

std::optional<Move> split_move(const World& w, const MapEvidence& ev, const SplitCandidate& c, bool with_door) {
  const Unit& u = *w.find_unit(c.unit);
  const UnitId id = w.next_unit_id();
  const Unit a = ev.make_unit(id, c.first, u.lut_class), b = ev.make_unit(id + 1, c.second, u.lut_class);
  const Frame f(u.rect.theta);
  const Box ba = own_box(a.rect), bb = own_box(b.rect);
  Move m;
  m.kind = KernelKind::Split;
  m.units = {{u.id, u, std::nullopt}, {a.id, std::nullopt, a}, {b.id, std::nullopt, b}};
  for (const Door& d : w.doors()) {
    if (d.unit_a != u.id && d.unit_b != u.id) continue;
    const Point2 mid = f.to_local({0.5 * (d.a.x + d.b.x), 0.5 * (d.a.y + d.b.y)});
    const double da = distance_to_boundary(ba, mid), db = distance_to_boundary(bb, mid);
    if (std::min(da, db) > kMergeDoorSnap) return std::nullopt;
    const UnitId owner = da <= db ? a.id : b.id, other = d.unit_a == u.id ? d.unit_b : d.unit_a;
    m.doors.push_back({d.id, d, ev.make_door(d.id, std::min(owner, other), std::max(owner, other), d.a, d.b)});
  }
  if (with_door) {
    if (!c.door) return std::nullopt;
    const DoorId did = w.next_door_id();
    m.doors.push_back({did, std::nullopt, ev.make_door(did, a.id, b.id, c.door->first, c.door->second)});
  }
  return m;
}

}  // namespace ksmc::stdlib::indoor::kit
