#include "stdlib/segments/proposals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ksmc::stdlib::segments {

namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

double log_sum_exp(const std::vector<double>& v) {
  double m = kNegInf;
  for (double x : v) m = std::max(m, x);
  if (!std::isfinite(m)) return m;
  double s = 0.0;
  for (double x : v) s += std::exp(x - m);
  return m + std::log(s);
}

}  // namespace

double log_normal2(Vec2 x, Vec2 mean, double sigma) {
  const Vec2 d = x - mean;
  return -dot(d, d) / (2.0 * sigma * sigma) - std::log(2.0 * kPi * sigma * sigma);
}

std::vector<double> birth_probabilities(const Scene& scene, const std::vector<Candidate>& cands,
                                        const BirthParams& p) {
  std::vector<double> w(cands.size(), 0.0);
  double total = 0.0;
  for (std::size_t c = 0; c < cands.size(); ++c) {
    std::size_t unexplained = 0;
    for (const auto i : cands[c].inliers)
      if (!(scene.distance(i) <= p.explained)) ++unexplained;
    w[c] = std::pow(1.0 + static_cast<double>(unexplained), p.power);
    total += w[c];
  }
  if (total > 0.0)
    for (double& x : w) x /= total;
  return w;
}

double birth_log_density(const Segment& s, const std::vector<double>& probs, const std::vector<Candidate>& cands,
                         const BirthParams& p) {
  std::vector<double> terms;
  terms.reserve(2 * cands.size());
  for (std::size_t c = 0; c < cands.size(); ++c) {
    if (!(probs[c] > 0.0)) continue;
    const double lw = std::log(probs[c]);
    const Segment& k = cands[c].seg;
    terms.push_back(lw + log_normal2(s.a, k.a, p.jitter) + log_normal2(s.b, k.b, p.jitter));
    terms.push_back(lw + log_normal2(s.a, k.b, p.jitter) + log_normal2(s.b, k.a, p.jitter));
  }
  return log_sum_exp(terms);
}

std::vector<double> death_probabilities(const Scene& scene, const DeathParams& p) {
  const std::size_t n = scene.size();
  std::vector<double> support(n, 0.0);
  for (std::size_t i = 0; i < scene.points().size(); ++i) {
    const int k = scene.nearest(i);
    if (k >= 0 && scene.distance(i) <= p.explain) support[static_cast<std::size_t>(k)] += 1.0;
  }
  std::vector<double> w(n, 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    w[k] = 1.0 / (1.0 + support[k]);
    total += w[k];
  }
  for (double& x : w) x /= total;
  return w;
}

std::vector<SplitOption> split_options(const std::vector<Vec2>& points, const Segment& s, const SplitParams& p) {
  const double len = s.length();
  const int bins = std::max(2, static_cast<int>(std::floor(len / p.bin + 1e-9)));
  std::vector<int> count(static_cast<std::size_t>(bins), 0);
  if (len > 0.0)
    for (const Vec2& q : points) {
      const double t = projection_param(q, s);
      if (t < 0.0 || t > 1.0 || point_line_distance(q, s) > p.near) continue;
      const int b = std::min(bins - 1, static_cast<int>(t * bins));
      ++count[static_cast<std::size_t>(b)];
    }
  // Options: the inner bin boundaries j = 1..bins-1. A boundary inside a run of empty bins
  // opens the whole run as a gap, with weight gap_weight; otherwise a cut (no gap), weight 1.
  std::vector<SplitOption> out;
  double total = 0.0;
  for (int j = 1; j < bins; ++j) {
    SplitOption o;
    const bool left_empty = count[static_cast<std::size_t>(j - 1)] == 0;
    const bool right_empty = count[static_cast<std::size_t>(j)] == 0;
    if (left_empty || right_empty) {
      int lo = j, hi = j;  // boundaries of the empty run
      while (lo > 0 && count[static_cast<std::size_t>(lo - 1)] == 0) --lo;
      while (hi < bins && count[static_cast<std::size_t>(hi)] == 0) ++hi;
      o.t_lo = static_cast<double>(lo) / bins;
      o.t_hi = static_cast<double>(hi) / bins;
      o.prob = p.gap_weight;
    } else {
      o.t_lo = o.t_hi = static_cast<double>(j) / bins;
      o.prob = 1.0;
    }
    total += o.prob;
    out.push_back(o);
  }
  for (auto& o : out) o.prob /= total;
  return out;
}

double split_log_density(const Segment& s, Vec2 p1, Vec2 p2, const std::vector<SplitOption>& options,
                         const SplitParams& p) {
  std::vector<double> terms;
  terms.reserve(options.size());
  const Vec2 d = s.b - s.a;
  for (const SplitOption& o : options)
    terms.push_back(std::log(o.prob) + log_normal2(p1, s.a + o.t_lo * d, p.jitter) +
                    log_normal2(p2, s.a + o.t_hi * d, p.jitter));
  return log_sum_exp(terms);
}

std::pair<Segment, Segment> split_pieces(const Segment& s, Vec2 p1, Vec2 p2) {
  return {canonical(s.a, p1), canonical(p2, s.b)};
}

Merged merge_of(const Segment& s, const Segment& t) {
  const Vec2 es[2] = {s.a, s.b};
  const Vec2 ft[2] = {t.a, t.b};
  int bi = 0, bj = 0;
  double best = -1.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double d = dist(es[i], ft[j]);
      if (d > best) {
        best = d;
        bi = i;
        bj = j;
      }
    }
  const Vec2 e = es[bi], f = ft[bj];
  const Vec2 e_other = es[1 - bi], f_other = ft[1 - bj];
  Merged m;
  m.seg = canonical(e, f);
  if (m.seg.a == e) {
    m.p1 = e_other;
    m.p2 = f_other;
  } else {
    m.p1 = f_other;
    m.p2 = e_other;
  }
  return m;
}

double partner_weight(const Segment& s, const Segment& t, const MergeParams& p) {
  return std::exp(-undirected_angle(s, t) / p.angle_scale) / (p.eps + endpoint_gap(s, t));
}

double merge_pair_log_prob(const std::vector<Line>& lines, std::size_t i, std::size_t j, const MergeParams& p) {
  const std::size_t n = lines.size();
  auto one_way = [&](std::size_t x, std::size_t y) {
    double total = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (k != x) total += partner_weight(lines[x].seg, lines[k].seg, p);
    return partner_weight(lines[x].seg, lines[y].seg, p) / total;
  };
  return std::log((one_way(i, j) + one_way(j, i)) / static_cast<double>(n));
}

}  // namespace ksmc::stdlib::segments
