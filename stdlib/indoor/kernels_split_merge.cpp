// SPLIT / MERGE (seed §3.5.2). SPLIT: a member unit drawn uniformly, a split line inside it
// drawn by omega_e = l(e) (eq. 3.18, times the orientation bias), extended across two opposite
// walls; the cut is taken perpendicular to those walls through the mean of the two crossings.
// MERGE: first unit uniform, second by a_r(s) = 1/d (eq. 3.19-3.20); the two must tile a
// rectangle exactly (same frame, a full common wall), which is the only case SPLIT can undo.
// Doors: both moves carry the doors of the units they remove to the units they add (each door
// to the one added unit with a wall under it). Before, a unit with a door could not be split
// or merged, so a unit spanning several offices froze from the first door ALLOCATE gave it
// (from iteration 4000 on: lab_c_scan kept one hall over six offices).
// Seam doors (KernelSources::seam_doors, `move.seam_doors`): SPLIT also allocates each door
// candidate found between its two halves with probability 1/2 (the distinct candidates, so a
// set of doors has probability 2^-n), and MERGE deletes the doors joining its two units, which
// it otherwise declines. So a corridor in pieces with a door between each two can be merged.
#include <algorithm>
#include <cmath>
#include <array>
#include <initializer_list>
#include <span>

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor::kernels {

namespace {

struct Cut {
  Box first, second;  // in the unit's own frame
};

std::optional<Cut> cut_of(const Context& c, const OrientedRect& r, const CandidateLine& line) {
  const Frame f(r.theta);
  const Box b = own_box(r);
  const Point2 p = f.to_local(line.a), q = f.to_local(line.b);
  const double dx = q.x - p.x, dy = q.y - p.y;
  if (std::abs(dx) < 1e-12 && std::abs(dy) < 1e-12) return std::nullopt;
  Cut cut;
  if (std::abs(dx) >= std::abs(dy)) {  // crosses the x0 and x1 walls
    const double y0 = p.y + (b.x0 - p.x) * dy / dx, y1 = p.y + (b.x1 - p.x) * dy / dx;
    if (!(y0 > b.y0 && y0 < b.y1 && y1 > b.y0 && y1 < b.y1)) return std::nullopt;
    const double pos = 0.5 * (y0 + y1);
    cut = {{b.x0, b.x1, b.y0, pos}, {b.x0, b.x1, pos, b.y1}};
  } else {  // crosses the y0 and y1 walls
    const double x0 = p.x + (b.y0 - p.y) * dx / dy, x1 = p.x + (b.y1 - p.y) * dx / dy;
    if (!(x0 > b.x0 && x0 < b.x1 && x1 > b.x0 && x1 < b.x1)) return std::nullopt;
    const double pos = 0.5 * (x0 + x1);
    cut = {{b.x0, pos, b.y0, b.y1}, {pos, b.x1, b.y0, b.y1}};
  }
  for (const Box& x : {cut.first, cut.second})
    if (x.width() < c.p.min_size || x.height() < c.p.min_size) return std::nullopt;
  return cut;
}

std::vector<double> line_weights(const Context& c, const std::vector<CandidateLine>& lines) {
  std::vector<double> w;
  w.reserve(lines.size());
  for (const auto& l : lines) {
    const double len = distance(l.a, l.b);
    const double base = l.weight > 0.0 ? l.weight : len;
    const double v = base * c.p.orientation.factor(std::atan2(l.b.y - l.a.y, l.b.x - l.a.x));
    w.push_back(std::isfinite(v) && v > 0.0 ? v : 0.0);
  }
  return w;
}

// log of the total normalised weight of the lines whose cut of `r` yields {a, b}.
double log_cut_mass(const Context& c, const OrientedRect& r, const std::vector<CandidateLine>& lines,
                    const std::vector<double>& w, const OrientedRect& a, const OrientedRect& b) {
  double total = 0.0, mass = 0.0;
  const Frame f(r.theta);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    total += w[i];
    if (!(w[i] > 0.0)) continue;
    const auto cut = cut_of(c, r, lines[i]);
    if (!cut) continue;
    const OrientedRect p = rect_from_box(cut->first, f), q = rect_from_box(cut->second, f);
    if ((same_rect(p, a, c.p.coincide) && same_rect(q, b, c.p.coincide)) ||
        (same_rect(p, b, c.p.coincide) && same_rect(q, a, c.p.coincide)))
      mass += w[i];
  }
  return (total > 0.0 && mass > 0.0) ? std::log(mass / total) : kNegInf;
}

// The rectangle tiled exactly by r and s, if any.
std::optional<OrientedRect> merged(const Context& c, const OrientedRect& r, const OrientedRect& s) {
  const Frame f(r.theta);
  const auto br = box_in_frame(r, f, c.p.align_angle), bs = box_in_frame(s, f, c.p.align_angle);
  if (!br || !bs) return std::nullopt;
  const double e = c.p.coincide;
  auto eq = [e](double x, double y) { return std::abs(x - y) <= e; };
  const bool same_x = eq(br->x0, bs->x0) && eq(br->x1, bs->x1);
  const bool same_y = eq(br->y0, bs->y0) && eq(br->y1, bs->y1);
  const bool stacked = same_x && (eq(br->y1, bs->y0) || eq(bs->y1, br->y0));
  const bool beside = same_y && (eq(br->x1, bs->x0) || eq(bs->x1, br->x0));
  if (!stacked && !beside) return std::nullopt;
  const Box u{std::min(br->x0, bs->x0), std::max(br->x1, bs->x1), std::min(br->y0, bs->y0),
              std::max(br->y1, bs->y1)};
  return rect_from_box(u, f);
}

// The one unit of `among` with a wall under door d (door_wall_distance), or nullopt.
std::optional<UnitId> owner_of(const Context& c, const Door& d, std::span<const Unit> among) {
  std::optional<UnitId> owner;
  for (const Unit& u : among) {
    if (!std::isfinite(door_wall_distance(c, u.rect, d.a, d.b))) continue;
    if (owner) return std::nullopt;
    owner = u.id;
  }
  return owner;
}

// The doors of the units `from` (removed by the move) re-attached to the units `to` (added by
// it): each to its one owner in `to`. nullopt (the move is not made) when a door joins two
// units of `from`, has no single owner in `to`, or has not its own unit as single owner in
// `from`. The last condition is the first one of the reverse move, so a move carries its doors
// exactly when its reverse carries them back: the door changes are a function of the unit
// changes, and the proposal densities stay those of the units.
// With `delete_shared`, a door joining two units of `from` is deleted instead (MERGE with seam
// doors).
std::optional<std::vector<DoorChange>> carry_doors(const Context& c, const World& w, std::span<const Unit> from,
                                                   std::span<const Unit> to, bool delete_shared = false) {
  auto in_from = [&](UnitId id) {
    return std::any_of(from.begin(), from.end(), [id](const Unit& u) { return u.id == id; });
  };
  std::vector<DoorChange> out;
  for (const Door& d : w.doors()) {
    const bool fa = in_from(d.unit_a), fb = in_from(d.unit_b);
    if (!fa && !fb) continue;
    if (fa && fb) {
      if (!delete_shared) return std::nullopt;
      out.push_back({d.id, d, std::nullopt});
      continue;
    }
    const UnitId mine = fa ? d.unit_a : d.unit_b, other = fa ? d.unit_b : d.unit_a;
    const auto back = owner_of(c, d, from);
    const auto owner = owner_of(c, d, to);
    if (!back || *back != mine || !owner) return std::nullopt;
    Door moved = d;
    moved.unit_a = std::min(*owner, other);
    moved.unit_b = std::max(*owner, other);
    out.push_back({d.id, d, moved});
  }
  return out;
}

// The move's changes of existing doors are exactly `carry_doors` of its unit changes (doors
// it adds, SPLIT's seam doors, are checked by `seam_doors_match`).
bool carries_doors(const Context& c, const World& w, const Move& m, std::initializer_list<const UnitChange*> removed,
                   std::initializer_list<const UnitChange*> added, bool delete_shared = false) {
  std::vector<Unit> from, to;
  for (const UnitChange* ch : removed) from.push_back(*w.find_unit(ch->id));
  for (const UnitChange* ch : added) to.push_back(*ch->after);
  const auto want = carry_doors(c, w, from, to, delete_shared);
  std::vector<const DoorChange*> existing;
  for (const DoorChange& y : m.doors)
    if (y.before) existing.push_back(&y);
  if (!want || want->size() != existing.size()) return false;
  for (std::size_t i = 0; i < want->size(); ++i) {
    const DoorChange& x = (*want)[i];
    const DoorChange& y = *existing[i];
    if (x.id != y.id || y.before->unit_a != x.before->unit_a || y.before->unit_b != x.before->unit_b ||
        x.after.has_value() != y.after.has_value())
      return false;
    if (x.after && (y.after->unit_a != x.after->unit_a || y.after->unit_b != x.after->unit_b ||
                    distance(y.after->a, x.after->a) > c.p.coincide || distance(y.after->b, x.after->b) > c.p.coincide))
      return false;
  }
  return true;
}

// The distinct door candidates on the cut between a and b (none without a seam source).
std::vector<CandidateDoor> seam_candidates(const Context& c, const OrientedRect& a, const OrientedRect& b) {
  std::vector<CandidateDoor> out;
  if (!c.src.seam_doors) return out;
  for (const CandidateDoor& k : c.src.seam_doors(a, b)) {
    if (!std::isfinite(k.a.x) || !std::isfinite(k.a.y) || !std::isfinite(k.b.x) || !std::isfinite(k.b.y)) continue;
    const bool seen = std::any_of(out.begin(), out.end(),
                                  [&](const CandidateDoor& o) { return same_segment(c, o.a, o.b, k.a, k.b); });
    if (!seen) out.push_back(k);
  }
  return out;
}

// The doors m adds are a subset of the seam candidates between units ua and ub (new ids, one
// candidate each).
bool seam_doors_match(const Context& c, const World& w, const Move& m, const std::vector<CandidateDoor>& seam,
                      UnitId ua, UnitId ub) {
  std::vector<bool> used(seam.size(), false);
  for (const DoorChange& y : m.doors) {
    if (y.before) continue;
    if (!y.after || w.find_door(y.id) || y.after->unit_a != std::min(ua, ub) || y.after->unit_b != std::max(ua, ub))
      return false;
    bool found = false;
    for (std::size_t j = 0; j < seam.size() && !found; ++j)
      if (!used[j] && same_segment(c, seam[j].a, seam[j].b, y.after->a, y.after->b)) used[j] = found = true;
    if (!found) return false;
  }
  return true;
}

}  // namespace

std::optional<Forward> propose_split(const Context& c, const World& w, Rng& rng) {
  const auto units = w.units();
  if (units.empty() || !c.src.split_lines) return std::nullopt;
  const auto i = std::uniform_int_distribution<std::size_t>(0, units.size() - 1)(rng);
  const Unit& u = units[i];
  const auto lines = c.src.split_lines(w, u);
  const auto lw = line_weights(c, lines);
  const auto e = draw_weighted(lw, rng);
  if (!e) return std::nullopt;
  const auto cut = cut_of(c, u.rect, lines[*e]);
  if (!cut) return std::nullopt;
  const Frame f(u.rect.theta);
  const UnitId id = w.next_unit_id();
  const Unit a = c.ev.make_unit(id, rect_from_box(cut->first, f), u.lut_class);
  const Unit b = c.ev.make_unit(id + 1, rect_from_box(cut->second, f), u.lut_class);
  const std::array<Unit, 2> halves{a, b};
  auto doors = carry_doors(c, w, std::span<const Unit>(&u, 1), halves);
  if (!doors) return std::nullopt;
  const auto seam = seam_candidates(c, a.rect, b.rect);
  DoorId next = w.next_door_id();
  for (const CandidateDoor& k : seam)
    if (std::bernoulli_distribution(0.5)(rng)) {
      const Door d = c.ev.make_door(next++, std::min(a.id, b.id), std::max(a.id, b.id), k.a, k.b);
      doors->push_back({d.id, std::nullopt, d});
    }
  Forward fw;
  fw.move.kind = KernelKind::Split;
  fw.move.units = {{u.id, u, std::nullopt}, {a.id, std::nullopt, a}, {b.id, std::nullopt, b}};
  fw.move.doors = std::move(*doors);
  fw.log_q = -std::log(static_cast<double>(units.size())) + log_cut_mass(c, u.rect, lines, lw, a.rect, b.rect) +
             static_cast<double>(seam.size()) * std::log(0.5);
  return fw;
}

double log_q_split(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (!c.src.split_lines || s.removed.size() != 1 || s.added.size() != 2 || !s.modified.empty()) return kNegInf;
  const UnitChange& ch = *s.removed[0];
  if (!unit_matches(c, w, ch.id, ch.before->rect) || !carries_doors(c, w, m, {&ch}, {s.added[0], s.added[1]}))
    return kNegInf;
  const auto seam = seam_candidates(c, s.added[0]->after->rect, s.added[1]->after->rect);
  if (!seam_doors_match(c, w, m, seam, s.added[0]->id, s.added[1]->id)) return kNegInf;
  const Unit& u = *w.find_unit(ch.id);
  const auto lines = c.src.split_lines(w, u);
  return -std::log(static_cast<double>(w.units().size())) +
         log_cut_mass(c, u.rect, lines, line_weights(c, lines), s.added[0]->after->rect,
                      s.added[1]->after->rect) +
         static_cast<double>(seam.size()) * std::log(0.5);
}

std::optional<Forward> propose_merge(const Context& c, const World& w, Rng& rng) {
  const auto pair = draw_pair(w, rng);
  if (!pair) return std::nullopt;
  const Unit& r = w.units()[pair->first];
  const Unit& s = w.units()[pair->second];
  const auto rect = merged(c, r.rect, s.rect);
  if (!rect) return std::nullopt;
  // The merged unit keeps the larger unit's likelihood class.
  const std::uint8_t cls = r.rect.area() >= s.rect.area() ? r.lut_class : s.lut_class;
  const Unit u = c.ev.make_unit(w.next_unit_id(), *rect, cls);
  const std::array<Unit, 2> parts{r, s};
  auto doors = carry_doors(c, w, parts, std::span<const Unit>(&u, 1), static_cast<bool>(c.src.seam_doors));
  if (!doors) return std::nullopt;
  Forward fw;
  fw.move.kind = KernelKind::Merge;
  fw.move.units = {{r.id, r, std::nullopt}, {s.id, s, std::nullopt}, {u.id, std::nullopt, u}};
  fw.move.doors = std::move(*doors);
  fw.log_q = log_pair_probability(w, r.id, s.id);
  return fw;
}

double log_q_merge(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (s.removed.size() != 2 || s.added.size() != 1 || !s.modified.empty()) return kNegInf;
  const UnitChange& a = *s.removed[0];
  const UnitChange& b = *s.removed[1];
  if (!unit_matches(c, w, a.id, a.before->rect) || !unit_matches(c, w, b.id, b.before->rect)) return kNegInf;
  const auto rect = merged(c, w.find_unit(a.id)->rect, w.find_unit(b.id)->rect);
  if (!rect || !same_rect(*rect, s.added[0]->after->rect, c.p.coincide)) return kNegInf;
  if (!carries_doors(c, w, m, {&a, &b}, {s.added[0]}, static_cast<bool>(c.src.seam_doors))) return kNegInf;
  for (const DoorChange& y : m.doors)
    if (!y.before) return kNegInf;  // MERGE adds no door
  return log_pair_probability(w, a.id, b.id);
}

}  // namespace ksmc::stdlib::indoor::kernels
