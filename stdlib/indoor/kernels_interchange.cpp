// INTERCHANGE (seed §3.5.2, Fig. 3.19): restructure two units that share a wall. The first
// unit is drawn uniformly, the second by a_r(s) = 1/d (eq. 3.26-3.27); then with probability
// 1/2 each:
//   variant 0, shift: the shared wall moves by a zero-mean Gaussian amount (one unit grows, the
//     other shrinks); the reverse moves it back.
//   variant 1, swap the junction: two units forming an L (shared wall, one end aligned) are
//     re-cut along the other wall through the inner corner; applying it twice restores them.
// Both variants are their own reverse. The ids stay: in a swap, the new piece without the inner
// corner takes the id of the old piece that had it (it lies inside that piece).
#include <algorithm>
#include <cmath>

#include "stdlib/indoor/kernel_common.h"

namespace ksmc::stdlib::indoor::kernels {

namespace {

Box transpose(const Box& b) { return {b.y0, b.y1, b.x0, b.x1}; }

struct Shared {
  int axis = 0;       // 0: the shared wall is a line x = const, 1: y = const
  bool a_low = true;  // A lies on the low-coordinate side of it
};

double overlap(double a0, double a1, double b0, double b1) { return std::min(a1, b1) - std::max(a0, b0); }

std::optional<Shared> shared_wall(const Box& a, const Box& b, double e) {
  if (overlap(a.y0, a.y1, b.y0, b.y1) > e) {
    if (std::abs(a.x1 - b.x0) <= e) return Shared{0, true};
    if (std::abs(b.x1 - a.x0) <= e) return Shared{0, false};
  }
  if (overlap(a.x0, a.x1, b.x0, b.x1) > e) {
    if (std::abs(a.y1 - b.y0) <= e) return Shared{1, true};
    if (std::abs(b.y1 - a.y0) <= e) return Shared{1, false};
  }
  return std::nullopt;
}

// Boxes for (A', B') in the common frame, or nullopt.
std::optional<std::pair<Box, Box>> restructure(const Context& c, Box a, Box b, int variant, double delta) {
  const double e = c.p.coincide;
  const auto sh = shared_wall(a, b, e);
  if (!sh) return std::nullopt;
  if (sh->axis == 1) {
    a = transpose(a);
    b = transpose(b);
  }
  Box na = a, nb = b;
  if (variant == 0) {
    if (sh->a_low) {
      na.x1 += delta;
      nb.x0 += delta;
    } else {
      na.x0 -= delta;
      nb.x1 -= delta;
    }
  } else {
    const Box& l = sh->a_low ? a : b;
    const Box& r = sh->a_low ? b : a;
    const bool top = std::abs(l.y0 - r.y0) <= e, bottom = std::abs(l.y1 - r.y1) <= e;
    if (top == bottom) return std::nullopt;  // a rectangle (MERGE's case) or no L
    const bool a_tall = a.height() > b.height();
    const Box& t = a_tall ? a : b;  // the piece holding the inner corner
    const Box& s = a_tall ? b : a;
    const Box band = top ? Box{l.x0, r.x1, t.y0, s.y1} : Box{l.x0, r.x1, s.y0, t.y1};
    const Box rest = top ? Box{t.x0, t.x1, s.y1, t.y1} : Box{t.x0, t.x1, t.y0, s.y0};
    na = a_tall ? rest : band;
    nb = a_tall ? band : rest;
  }
  for (const Box& x : {na, nb})
    if (x.width() < c.p.min_size || x.height() < c.p.min_size) return std::nullopt;
  if (sh->axis == 1) {
    na = transpose(na);
    nb = transpose(nb);
  }
  return std::make_pair(na, nb);
}

// New rectangles of units r and s (r's frame), or nullopt.
std::optional<std::pair<OrientedRect, OrientedRect>> interchange(const Context& c, const OrientedRect& r,
                                                                 const OrientedRect& s, int variant,
                                                                 double delta) {
  const Frame f(r.theta);
  const auto br = box_in_frame(r, f, c.p.align_angle), bs = box_in_frame(s, f, c.p.align_angle);
  if (!br || !bs) return std::nullopt;
  const auto boxes = restructure(c, *br, *bs, variant, delta);
  if (!boxes) return std::nullopt;
  return std::make_pair(rect_from_box(boxes->first, f), rect_from_box(boxes->second, f));
}

double log_variant(const Context& c, int variant, double delta) {
  return std::log(0.5) + (variant == 0 ? log_normal_pdf(delta, c.p.interchange_sigma) : 0.0);
}

}  // namespace

std::optional<Forward> propose_interchange(const Context& c, const World& w, Rng& rng) {
  const auto pair = draw_pair(w, rng);
  if (!pair) return std::nullopt;
  const int variant = std::uniform_int_distribution<int>(0, 1)(rng);
  const double delta = variant == 0 ? std::normal_distribution<double>(0.0, c.p.interchange_sigma)(rng) : 0.0;
  const Unit& r = w.units()[pair->first];
  const Unit& s = w.units()[pair->second];
  if (w.door_count(r.id) > 0 || w.door_count(s.id) > 0) return std::nullopt;
  const auto rects = interchange(c, r.rect, s.rect, variant, delta);
  if (!rects) return std::nullopt;
  Forward f;
  f.move.kind = KernelKind::Interchange;
  f.move.units = {{r.id, r, c.ev.make_unit(r.id, rects->first, r.lut_class)},
                  {s.id, s, c.ev.make_unit(s.id, rects->second, s.lut_class)}};
  f.move.detail.variant = variant;
  f.move.detail.delta = delta;
  f.log_q = log_pair_probability(w, r.id, s.id) + log_variant(c, variant, delta);
  return f;
}

double log_q_interchange(const Context& c, const World& w, const Move& m) {
  const Shape s = shape_of(m);
  if (m.units.size() != 2 || s.modified.size() != 2 || !m.doors.empty()) return kNegInf;
  const int variant = m.detail.variant;
  if (variant != 0 && variant != 1) return kNegInf;
  const UnitChange& a = m.units[0];
  const UnitChange& b = m.units[1];
  if (a.id == b.id || !unit_free(c, w, a.id, a.before->rect) || !unit_free(c, w, b.id, b.before->rect))
    return kNegInf;
  const double delta = variant == 0 ? m.detail.delta : 0.0;
  const auto rects = interchange(c, w.find_unit(a.id)->rect, w.find_unit(b.id)->rect, variant, delta);
  if (!rects || !same_rect(rects->first, a.after->rect, c.p.coincide) ||
      !same_rect(rects->second, b.after->rect, c.p.coincide))
    return kNegInf;
  return log_pair_probability(w, a.id, b.id) + log_variant(c, variant, delta);
}

}  // namespace ksmc::stdlib::indoor::kernels
