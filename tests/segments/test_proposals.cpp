#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "runtime/mcmc/rng.h"
#include "stdlib/segments/detect.h"
#include "stdlib/segments/proposals.h"

using namespace ksmc::stdlib::segments;
using ksmc::runtime::mcmc::Rng;

namespace {

// Points along y = 0 from x = 0 to 3 every 5 cm, with a gap over (1.2, 2.0).
std::shared_ptr<const std::vector<Vec2>> wall_with_gap() {
  auto pts = std::make_shared<std::vector<Vec2>>();
  for (int i = 0; i <= 60; ++i) {
    if (i > 24 && i < 40) continue;
    pts->push_back({0.05 * i, 0.0});
  }
  return pts;
}

}  // namespace

TEST_CASE("RANSAC finds the wall pieces deterministically", "[segments][detect]") {
  const auto pts = wall_with_gap();
  RansacParams p;
  p.min_inliers = 8;
  p.candidates = 20;
  const auto a = detect_candidates(*pts, p, 5);
  const auto b = detect_candidates(*pts, p, 5);
  REQUIRE(!a.empty());
  REQUIRE(a.size() == b.size());
  bool left = false, right = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].seg == b[i].seg);
    const Segment& s = a[i].seg;
    left = left || (std::abs(s.a.x) < 0.01 && std::abs(s.b.x - 1.2) < 0.01);
    right = right || (std::abs(s.a.x - 2.0) < 0.01 && std::abs(s.b.x - 3.0) < 0.01);
    CHECK(s.length() < 1.3);  // never across the 0.8 m gap (max_gap 0.3 m)
  }
  CHECK(left);
  CHECK(right);
}

TEST_CASE("birth density is the canonicalised Gaussian mixture", "[segments][proposals]") {
  const auto pts = wall_with_gap();
  Scene scene(pts, {0.02, 0.05});
  std::vector<Candidate> cands(2);
  cands[0].seg = {{0, 0}, {1.2, 0}};
  cands[1].seg = {{2, 0}, {3, 0}};
  for (std::uint32_t i = 0; i < pts->size(); ++i) ((*pts)[i].x < 1.5 ? cands[0] : cands[1]).inliers.push_back(i);
  BirthParams bp;
  bp.power = 1.0;
  auto probs = birth_probabilities(scene, cands, bp);
  const double n0 = static_cast<double>(cands[0].inliers.size()), n1 = static_cast<double>(cands[1].inliers.size());
  CHECK(probs[0] == Approx((1 + n0) / (2 + n0 + n1)));
  // Explain candidate 0's points: its weight drops to 1.
  const Segment add[1] = {cands[0].seg};
  scene.change({}, add);
  probs = birth_probabilities(scene, cands, bp);
  CHECK(probs[0] == Approx(1.0 / (2 + n1)));
  const Segment s = canonical({0.01, 0.02}, {1.18, -0.01});
  const double expect = std::log(probs[0] * (std::exp(log_normal2(s.a, cands[0].seg.a, bp.jitter) + log_normal2(s.b, cands[0].seg.b, bp.jitter)) +
                                             std::exp(log_normal2(s.a, cands[0].seg.b, bp.jitter) + log_normal2(s.b, cands[0].seg.a, bp.jitter))) +
                                 probs[1] * (std::exp(log_normal2(s.a, cands[1].seg.a, bp.jitter) + log_normal2(s.b, cands[1].seg.b, bp.jitter)) +
                                             std::exp(log_normal2(s.a, cands[1].seg.b, bp.jitter) + log_normal2(s.b, cands[1].seg.a, bp.jitter))));
  CHECK(birth_log_density(s, probs, cands, bp) == Approx(expect));
}

TEST_CASE("death prefers poorly supported lines", "[segments][proposals]") {
  const auto pts = wall_with_gap();
  Scene scene(pts, {0.02, 0.05});
  const Segment add[2] = {{{0, 0}, {1.2, 0}}, {{0, 1}, {3, 1}}};  // the second explains nothing
  scene.change({}, add);
  const auto dp = death_probabilities(scene, {0.05});
  REQUIRE(dp.size() == 2);
  CHECK(dp[0] + dp[1] == Approx(1.0));
  CHECK(dp[1] / dp[0] == Approx(1.0 + 25.0));  // 25 points on [0, 1.2]
}

TEST_CASE("split options open the support gap; merge inverts split", "[segments][proposals]") {
  const auto pts = wall_with_gap();
  const Segment s{{0, 0}, {3, 0}};
  SplitParams sp;
  const auto opts = split_options(*pts, s, sp);
  REQUIRE(opts.size() == 29);  // 30 bins of 10 cm
  double total = 0.0, gap_mass = 0.0;
  for (const auto& o : opts) {
    total += o.prob;
    if (o.t_hi > o.t_lo) {
      gap_mass += o.prob;
      CHECK(o.t_lo * 3 == Approx(1.3));  // the empty bins [1.3, 2.0)
      CHECK(o.t_hi * 3 == Approx(2.0));
    }
  }
  CHECK(total == Approx(1.0));
  CHECK(gap_mass > 0.5);
  // Pieces of a split merge back to the segment and the same inner endpoints.
  Rng rng(2);
  for (int k = 0; k < 100; ++k) {
    const Vec2 p1{rng.uniform(0.2, 1.4), rng.normal(0, 0.02)}, p2{rng.uniform(1.6, 2.8), rng.normal(0, 0.02)};
    const auto [s1, s2] = split_pieces(s, p1, p2);
    const Merged m = merge_of(s2, s1);
    CHECK(m.seg == s);
    CHECK(m.p1 == p1);
    CHECK(m.p2 == p2);
    CHECK(std::isfinite(split_log_density(s, p1, p2, opts, sp)));
  }
}

TEST_CASE("merge pair probability sums both orders", "[segments][proposals]") {
  std::vector<Line> lines = {{{{0, 0}, {1, 0}}, 0}, {{{1.1, 0}, {2, 0}}, 1}, {{{0, 1}, {0, 2}}, 2}};
  MergeParams mp;
  auto w = [&](std::size_t i, std::size_t j) { return partner_weight(lines[i].seg, lines[j].seg, mp); };
  const double p01 = (w(0, 1) / (w(0, 1) + w(0, 2)) + w(1, 0) / (w(1, 0) + w(1, 2))) / 3.0;
  CHECK(std::exp(merge_pair_log_prob(lines, 0, 1, mp)) == Approx(p01));
  CHECK(merge_pair_log_prob(lines, 1, 0, mp) == Approx(merge_pair_log_prob(lines, 0, 1, mp)));
  double sum = 0.0;  // over unordered pairs
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = i + 1; j < 3; ++j) sum += std::exp(merge_pair_log_prob(lines, i, j, mp));
  CHECK(sum == Approx(1.0));
}
