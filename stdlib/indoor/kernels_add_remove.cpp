// ADD / REMOVE (seed §3.5.2): ADD draws a unit candidate by its weight omega_r (times the
// dominant-orientation bias); REMOVE draws a member unit by b_r (eq. 3.21).
#include <cmath>

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor::kernels {

namespace {

std::vector<double> candidate_weights(const Context& c, std::span<const CandidateUnit> cands) {
  std::vector<double> w;
  w.reserve(cands.size());
  for (const auto& k : cands) {
    const double v = k.weight * c.p.orientation.factor(k.rect.theta);
    const bool finite_rect = std::isfinite(k.rect.cx) && std::isfinite(k.rect.cy) && std::isfinite(k.rect.w) &&
                             std::isfinite(k.rect.h) && std::isfinite(k.rect.theta);
    w.push_back(std::isfinite(v) && v > 0.0 && finite_rect && k.rect.w > 0.0 && k.rect.h > 0.0 ? v : 0.0);
  }
  return w;
}

// Normalised weight of all candidates equal to `r` (duplicates add up).
double log_candidate_mass(const Context& c, std::span<const CandidateUnit> cands,
                          const std::vector<double>& w, const OrientedRect& r) {
  double total = 0.0, mass = 0.0;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    total += w[i];
    if (!(w[i] > 0.0)) continue;
    // Same rectangles share their centre: a cheap test before comparing corners.
    if (std::abs(cands[i].rect.cx - r.cx) > c.p.coincide || std::abs(cands[i].rect.cy - r.cy) > c.p.coincide)
      continue;
    if (same_rect(cands[i].rect, r, c.p.coincide)) mass += w[i];
  }
  return (total > 0.0 && mass > 0.0) ? std::log(mass / total) : kNegInf;
}

}  // namespace

std::optional<Forward> propose_add(const Context& c, const World& w, Rng& rng) {
  if (!c.src.units) return std::nullopt;
  const auto cands = c.src.units(w);
  const auto weights = candidate_weights(c, cands);
  const auto i = draw_weighted(weights, rng);
  if (!i) return std::nullopt;
  const Unit u = c.ev.make_unit(w.next_unit_id(), cands[*i].rect);
  Forward f;
  f.move.kind = KernelKind::Add;
  f.move.units.push_back({u.id, std::nullopt, u});
  f.log_q = log_candidate_mass(c, cands, weights, u.rect);
  return f;
}

double log_q_add(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (!c.src.units || s.added.size() != 1 || !s.removed.empty() || !s.modified.empty() || !m.doors.empty())
    return kNegInf;
  if (w.find_unit(s.added[0]->id)) return kNegInf;
  const auto cands = c.src.units(w);
  return log_candidate_mass(c, cands, candidate_weights(c, cands), s.added[0]->after->rect);
}

std::optional<Forward> propose_remove(const Context& c, const World& w, Rng& rng) {
  const auto b = unit_change_weights(c, w);
  const auto i = draw_weighted(b, rng);
  if (!i) return std::nullopt;
  const Unit& u = w.units()[*i];
  if (w.door_count(u.id) > 0) return std::nullopt;
  Forward f;
  f.move.kind = KernelKind::Remove;
  f.move.units.push_back({u.id, u, std::nullopt});
  f.log_q = log_normalized(b, *i);
  return f;
}

double log_q_remove(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (s.removed.size() != 1 || !s.added.empty() || !s.modified.empty() || !m.doors.empty()) return kNegInf;
  const UnitChange& ch = *s.removed[0];
  if (!unit_free(c, w, ch.id, ch.before->rect)) return kNegInf;
  return log_normalized(unit_change_weights(c, w), *unit_index(w, ch.id));
}

}  // namespace ksmc::stdlib::indoor::kernels
