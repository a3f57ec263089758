// ADD / REMOVE (seed §3.5.2): ADD draws a unit candidate by its weight omega_r (times the
// dominant-orientation bias); REMOVE draws a member unit by b_r (eq. 3.21).
// With KernelParams::uniform_share = s > 0 (move.uniform_rect), ADD is a mixture: with
// probability s a rectangle drawn uniformly (centre in the map, each side in [min_size, D] with
// D the map diagonal, orientation in [0, 90 deg): every rectangle once), otherwise a candidate.
// Its probability is taken against counting measure on the candidates plus Lebesgue measure
// (cells, radians) on the other rectangles, so a rectangle that is a candidate has
// (1 - s) x its normalised weight and any other rectangle s x the uniform density. REMOVE of a
// unit no detector proposes (one SPLIT, SHRINK / DILATE or INTERCHANGE made) then has a
// reverse; with s = 0 that reverse is 0 and such a REMOVE is always rejected.
#include <cmath>
#include <numbers>

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

double map_diagonal(const Context& c) {
  return std::hypot(static_cast<double>(c.ev.observed().rows), static_cast<double>(c.ev.observed().cols));
}

// log of the uniform component's density at r, or -inf outside its support.
double log_uniform_density(const Context& c, const OrientedRect& r) {
  const double rows = c.ev.observed().rows, cols = c.ev.observed().cols, d = map_diagonal(c);
  const double span = d - c.p.min_size;
  if (!(span > 0.0) || !(rows > 0.0) || !(cols > 0.0)) return kNegInf;
  // The representation with theta in [0, 90 deg): a quarter turn swaps the sides.
  const double quarter = 0.5 * std::numbers::pi;
  const double turns = std::floor(r.theta / quarter);
  if (!std::isfinite(turns)) return kNegInf;
  const bool odd = std::fmod(std::abs(turns), 2.0) == 1.0;
  const double w = odd ? r.h : r.w, h = odd ? r.w : r.h;
  const auto inside = [](double x, double lo, double hi) { return x >= lo && x <= hi; };
  if (!inside(r.cx, 0.0, cols) || !inside(r.cy, 0.0, rows) || !inside(w, c.p.min_size, d) || !inside(h, c.p.min_size, d))
    return kNegInf;
  return -std::log(quarter) - std::log(rows * cols) - 2.0 * std::log(span);
}

// log Q of ADD proposing r: the candidates' share on candidates, the uniform share elsewhere.
double log_add_probability(const Context& c, std::span<const CandidateUnit> cands, const std::vector<double>& w,
                           const OrientedRect& r) {
  const double s = c.p.uniform_share;
  const double on_candidates = log_candidate_mass(c, cands, w, r);
  if (on_candidates > kNegInf) return s < 1.0 ? std::log1p(-s) + on_candidates : kNegInf;
  return s > 0.0 ? std::log(s) + log_uniform_density(c, r) : kNegInf;
}

std::optional<OrientedRect> draw_uniform_rect(const Context& c, Rng& rng) {
  const double d = map_diagonal(c);
  if (!(d > c.p.min_size)) return std::nullopt;
  std::uniform_real_distribution<double> x(0.0, c.ev.observed().cols), y(0.0, c.ev.observed().rows),
      side(c.p.min_size, d), angle(0.0, 0.5 * std::numbers::pi);
  OrientedRect r;
  r.cx = x(rng);
  r.cy = y(rng);
  r.w = side(rng);
  r.h = side(rng);
  r.theta = angle(rng);
  return r;
}

}  // namespace

std::optional<Forward> propose_add(const Context& c, const World& w, Rng& rng) {
  const auto cands = c.src.units ? c.src.units(w) : std::span<const CandidateUnit>{};
  const auto weights = candidate_weights(c, cands);
  std::optional<OrientedRect> r;
  if (c.p.uniform_share > 0.0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < c.p.uniform_share) {
    r = draw_uniform_rect(c, rng);
  } else if (const auto i = draw_weighted(weights, rng)) {
    r = cands[*i].rect;
  }
  if (!r) return std::nullopt;
  const Unit u = c.ev.make_unit(w.next_unit_id(), *r);
  Forward f;
  f.move.kind = KernelKind::Add;
  f.move.units.push_back({u.id, std::nullopt, u});
  f.log_q = log_add_probability(c, cands, weights, u.rect);
  if (!(f.log_q > kNegInf)) return std::nullopt;
  return f;
}

double log_q_add(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (s.added.size() != 1 || !s.removed.empty() || !s.modified.empty() || !m.doors.empty()) return kNegInf;
  if (w.find_unit(s.added[0]->id)) return kNegInf;
  const auto cands = c.src.units ? c.src.units(w) : std::span<const CandidateUnit>{};
  return log_add_probability(c, cands, candidate_weights(c, cands), s.added[0]->after->rect);
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
