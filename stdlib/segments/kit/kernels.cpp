#include "stdlib/segments/kit/kernels.h"

#include <cmath>
#include <vector>

namespace ksmc::stdlib::segments::kit {

namespace mcmc = runtime::mcmc;

namespace {

// Index drawn from normalised probabilities (the last one on rounding).
std::size_t draw(const std::vector<double>& probs, mcmc::Rng& rng) {
  const double u = rng.uniform();
  double acc = 0.0;
  for (std::size_t i = 0; i < probs.size(); ++i) {
    acc += probs[i];
    if (u < acc) return i;
  }
  return probs.size() - 1;
}

Vec2 gaussian2(mcmc::Rng& rng, double sigma) {
  const double x = rng.normal(0.0, sigma);
  const double y = rng.normal(0.0, sigma);
  return {x, y};
}

}  // namespace

mcmc::Proposal propose_birth(SegmentsModel& m, const KernelData& k, mcmc::Rng& rng) {
  const std::vector<Candidate>& cands = *k.candidates;
  if (cands.empty() || m.scene().size() >= m.shared().max_lines) return mcmc::Proposal::declined();
  const BirthParams& bp = k.params.birth;
  const auto probs = birth_probabilities(m.scene(), cands, bp);
  const Candidate& c = cands[draw(probs, rng)];
  const Vec2 a = c.seg.a + gaussian2(rng, bp.jitter);
  const Vec2 b = c.seg.b + gaussian2(rng, bp.jitter);
  const Segment s = canonical(a, b);
  const double fwd = birth_log_density(s, probs, cands, bp);
  const Segment add[1] = {s};
  const auto idx = m.change({}, add);
  const auto dp = death_probabilities(m.scene(), k.params.death);
  return mcmc::Proposal::made(fwd, std::log(dp[idx.at(0)]));
}

mcmc::Proposal propose_death(SegmentsModel& m, const KernelData& k, mcmc::Rng& rng) {
  if (m.scene().size() == 0) return mcmc::Proposal::declined();
  const auto dp = death_probabilities(m.scene(), k.params.death);
  const std::size_t i = draw(dp, rng);
  const Segment s = m.scene().lines()[i].seg;
  const double fwd = std::log(dp[i]);
  const std::size_t rm[1] = {i};
  m.change(rm, {});
  const auto probs = birth_probabilities(m.scene(), *k.candidates, k.params.birth);
  return mcmc::Proposal::made(fwd, birth_log_density(s, probs, *k.candidates, k.params.birth));
}

mcmc::Proposal propose_split(SegmentsModel& m, const KernelData& k, mcmc::Rng& rng) {
  const std::size_t n = m.scene().size();
  if (n == 0 || n >= m.shared().max_lines) return mcmc::Proposal::declined();
  const SplitParams& sp = k.params.split;
  const std::size_t i = rng.uniform_int(n);
  const Segment s = m.scene().lines()[i].seg;
  const auto options = split_options(m.scene().points(), s, sp);
  const SplitOption& o = options[draw([&] {
    std::vector<double> p;
    for (const auto& x : options) p.push_back(x.prob);
    return p;
  }(), rng)];
  const Vec2 d = s.b - s.a;
  const Vec2 p1 = s.a + o.t_lo * d + gaussian2(rng, sp.jitter);
  const Vec2 p2 = s.a + o.t_hi * d + gaussian2(rng, sp.jitter);
  const auto [s1, s2] = split_pieces(s, p1, p2);
  // MERGE recovers s from the pieces only when s's endpoints are their farthest pair.
  const Merged back = merge_of(s1, s2);
  if (!(back.seg == s && back.p1 == p1 && back.p2 == p2)) return mcmc::Proposal::declined();
  const double fwd = -std::log(static_cast<double>(n)) + split_log_density(s, p1, p2, options, sp);
  const std::size_t rm[1] = {i};
  const Segment add[2] = {s1, s2};
  const auto idx = m.change(rm, add);
  return mcmc::Proposal::made(fwd, merge_pair_log_prob(m.scene().lines(), idx[0], idx[1], k.params.merge));
}

mcmc::Proposal propose_merge(SegmentsModel& m, const KernelData& kd, mcmc::Rng& rng) {
  const std::size_t n = m.scene().size();
  if (n < 2) return mcmc::Proposal::declined();
  const auto& lines = m.scene().lines();
  const std::size_t i = rng.uniform_int(n);
  std::vector<double> w(n, 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (k != i) total += w[k] = partner_weight(lines[i].seg, lines[k].seg, kd.params.merge);
  for (double& x : w) x /= total;
  const std::size_t j = draw(w, rng);
  if (j == i) return mcmc::Proposal::declined();  // rounding only: w[i] = 0
  const double fwd = merge_pair_log_prob(lines, i, j, kd.params.merge);
  const Merged mg = merge_of(lines[i].seg, lines[j].seg);
  const std::size_t rm[2] = {i, j};
  const Segment add[1] = {mg.seg};
  m.change(rm, add);
  const auto options = split_options(m.scene().points(), mg.seg, kd.params.split);
  const double bwd = -std::log(static_cast<double>(n - 1)) +
                     split_log_density(mg.seg, mg.p1, mg.p2, options, kd.params.split);
  return mcmc::Proposal::made(fwd, bwd);
}

mcmc::Proposal propose_jitter(SegmentsModel& m, const KernelData& kd, mcmc::Rng& rng) {
  const std::size_t n = m.scene().size();
  if (n == 0) return mcmc::Proposal::declined();
  const JitterParams& jp = kd.params.jitter;
  const std::size_t k = rng.uniform_int(n);
  const Line line = m.scene().lines()[k];
  Segment moved;
  double lq = -std::log(static_cast<double>(n));
  const double u = rng.uniform();
  if (u < jp.shift_prob) {
    const Vec2 delta = gaussian2(rng, jp.sigma);
    moved = canonical(line.seg.a + delta, line.seg.b + delta);
    lq += std::log(jp.shift_prob) + log_normal2(delta, {0.0, 0.0}, jp.sigma);
  } else if (u < jp.shift_prob + jp.slide_prob) {
    // Along the segment's own line: the direction is unchanged, so the reverse slide uses
    // the same line (a flipped orientation only flips the sign of a symmetric step).
    const Vec2 dir = direction(line.seg);
    const double t = rng.normal(0.0, jp.slide);
    const bool first = rng.uniform_int(2) == 0;
    moved = first ? canonical(line.seg.a + t * dir, line.seg.b) : canonical(line.seg.a, line.seg.b + t * dir);
    lq += std::log(jp.slide_prob * 0.5) - 0.5 * (t / jp.slide) * (t / jp.slide) - std::log(jp.slide * std::sqrt(2.0 * kPi));
  } else {
    const Vec2 delta = gaussian2(rng, jp.sigma);
    moved = rng.uniform_int(2) == 0 ? canonical(line.seg.a + delta, line.seg.b) : canonical(line.seg.a, line.seg.b + delta);
    lq += std::log((1.0 - jp.shift_prob - jp.slide_prob) * 0.5) + log_normal2(delta, {0.0, 0.0}, jp.sigma);
  }
  // Symmetric: the reverse move picks the same line, the same endpoint (or shift), -delta.
  const std::size_t rm[1] = {k};
  const Segment add[1] = {moved};
  const std::uint64_t ids[1] = {line.id};
  m.change(rm, add, ids);
  return mcmc::Proposal::made(lq, lq);
}

mcmc::Proposal SegmentKernel::propose_typed(SegmentsModel& model, mcmc::Rng& rng) const {
  switch (data_.params.move) {
    case blocks::Move::birth: return propose_birth(model, data_, rng);
    case blocks::Move::death: return propose_death(model, data_, rng);
    case blocks::Move::split: return propose_split(model, data_, rng);
    case blocks::Move::merge: return propose_merge(model, data_, rng);
    case blocks::Move::jitter: return propose_jitter(model, data_, rng);
  }
  return mcmc::Proposal::declined();
}

}  // namespace ksmc::stdlib::segments::kit
