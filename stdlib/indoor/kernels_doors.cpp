// ALLOCATE / DELETE (seed §3.5.2): ALLOCATE draws a door candidate by omega_g (eq. 3.23) and
// assigns it to the two units whose walls it lies on (the two nearest walls parallel to the
// segment within door_snap cells whose extent contains its midpoint); DELETE draws an assigned
// door by z_g (eq. 3.28).
#include <algorithm>
#include <cmath>

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor::kernels {

namespace {

std::optional<std::pair<UnitId, UnitId>> attach(const Context& c, const World& w, Point2 a, Point2 b) {
  if (!(distance(a, b) > 0.0)) return std::nullopt;
  struct Hit {
    double d;
    UnitId id;
  };
  std::vector<Hit> hits;
  for (const Unit& u : w.units()) {
    const double best = door_wall_distance(c, u.rect, a, b);
    if (std::isfinite(best)) hits.push_back({best, u.id});
  }
  if (hits.size() < 2) return std::nullopt;
  std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.d != y.d ? x.d < y.d : x.id < y.id; });
  return std::make_pair(std::min(hits[0].id, hits[1].id), std::max(hits[0].id, hits[1].id));
}

// True when segment a-b lies along door d's doorway: parallel within door_angle, its
// midpoint within 2 door_snap of d's line (one wall's thickness), and the two extents along
// that line overlapping. Door candidates are detected again at every refresh, a few tenths of a
// cell apart; without this the chain stacked copies of one doorway (a copy slightly off covers
// a few cells the first does not): 21 doors for 4 doorways on a synthetic plan.
bool along_doorway(const Context& c, const Door& d, Point2 a, Point2 b) {
  const double len = distance(d.a, d.b), len_ab = distance(a, b);
  if (!(len > 0.0) || !(len_ab > 0.0)) return false;
  const double ux = (d.b.x - d.a.x) / len, uy = (d.b.y - d.a.y) / len;
  const double vx = (b.x - a.x) / len_ab, vy = (b.y - a.y) / len_ab;
  if (std::abs(ux * vy - uy * vx) > std::sin(c.p.door_angle)) return false;
  const Point2 mid{(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
  if (std::abs((mid.x - d.a.x) * uy - (mid.y - d.a.y) * ux) > 2.0 * c.p.door_snap) return false;
  const double ta = (a.x - d.a.x) * ux + (a.y - d.a.y) * uy, tb = (b.x - d.a.x) * ux + (b.y - d.a.y) * uy;
  return std::min(len, std::max(ta, tb)) - std::max(0.0, std::min(ta, tb)) > 0.0;
}

// A door at a-b is not proposed when a door already lies along the same doorway, whichever two
// units it joins: one doorway, one door (a copy also came attached to a thin unit lying along
// the wall beside the doorway).
bool already_assigned(const Context& c, const World& w, Point2 a, Point2 b) {
  for (const Door& d : w.doors())
    if (same_segment(c, d.a, d.b, a, b) || along_doorway(c, d, a, b)) return true;
  return false;
}

std::vector<double> door_candidate_weights(std::span<const CandidateDoor> cands) {
  std::vector<double> v;
  v.reserve(cands.size());
  for (const auto& k : cands) v.push_back(std::isfinite(k.weight) && k.weight > 0.0 ? k.weight : 0.0);
  return v;
}

double log_door_mass(const Context& c, std::span<const CandidateDoor> cands, const std::vector<double>& v,
                     Point2 a, Point2 b) {
  double total = 0.0, mass = 0.0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    total += v[i];
    if (v[i] > 0.0 && same_segment(c, cands[i].a, cands[i].b, a, b)) mass += v[i];
  }
  return (total > 0.0 && mass > 0.0) ? std::log(mass / total) : kNegInf;
}

std::vector<double> delete_weights(const Context& c, const World& w) {
  std::vector<double> z;
  z.reserve(w.doors().size());
  for (const Door& d : w.doors()) z.push_back(capped_inverse(d.weight, c.p.h_g));
  return z;
}

}  // namespace

std::optional<Forward> propose_allocate(const Context& c, const World& w, Rng& rng) {
  if (!c.src.doors) return std::nullopt;
  const auto cands = c.src.doors(w);
  const auto v = door_candidate_weights(cands);
  const auto i = draw_weighted(v, rng);
  if (!i) return std::nullopt;
  const CandidateDoor& k = cands[*i];
  if (already_assigned(c, w, k.a, k.b)) return std::nullopt;
  const auto units = attach(c, w, k.a, k.b);
  if (!units) return std::nullopt;
  const Door d = c.ev.make_door(w.next_door_id(), units->first, units->second, k.a, k.b);
  Forward f;
  f.move.kind = KernelKind::Allocate;
  f.move.doors.push_back({d.id, std::nullopt, d});
  f.log_q = log_door_mass(c, cands, v, k.a, k.b);
  return f;
}

double log_q_allocate(const Context& c, const World& w, const Move& m) {
  if (!c.src.doors || !m.units.empty() || m.doors.size() != 1 || m.doors[0].before || !m.doors[0].after)
    return kNegInf;
  const Door& d = *m.doors[0].after;
  if (w.find_door(d.id) || already_assigned(c, w, d.a, d.b)) return kNegInf;
  const auto units = attach(c, w, d.a, d.b);
  if (!units || units->first != d.unit_a || units->second != d.unit_b) return kNegInf;
  const auto cands = c.src.doors(w);
  return log_door_mass(c, cands, door_candidate_weights(cands), d.a, d.b);
}

std::optional<Forward> propose_delete(const Context& c, const World& w, Rng& rng) {
  const auto z = delete_weights(c, w);
  const auto i = draw_weighted(z, rng);
  if (!i) return std::nullopt;
  const Door& d = w.doors()[*i];
  Forward f;
  f.move.kind = KernelKind::Delete;
  f.move.doors.push_back({d.id, d, std::nullopt});
  f.log_q = log_normalized(z, *i);
  return f;
}

double log_q_delete(const Context& c, const World& w, const Move& m) {
  if (!m.units.empty() || m.doors.size() != 1 || !m.doors[0].before || m.doors[0].after) return kNegInf;
  const auto doors = w.doors();
  for (std::size_t i = 0; i < doors.size(); ++i)
    if (doors[i].id == m.doors[0].id) return log_normalized(delete_weights(c, w), i);
  return kNegInf;
}

}  // namespace ksmc::stdlib::indoor::kernels
