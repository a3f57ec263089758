// Each kernel pair's densities agree: for a move M -> M' by a kernel (the one that adds
// lines: an exact continuous state cannot be re-drawn), the reverse kernel, run on M'
// until it proposes exactly M, reports log Q(M|M') equal to the first kernel's
// log_q_bwd and log Q(M'|M) equal to its log_q_fwd (each computed by its own code).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "kit_fixture.h"
#include "runtime/mcmc/rng.h"

using namespace ksmc::stdlib::segments;
using namespace ksmc::stdlib::segments::kit;
using ksmc::runtime::mcmc::Proposal;
using ksmc::runtime::mcmc::Rng;
using Fn = Proposal (*)(SegmentsModel&, Rng&);

namespace {

// The state as a sorted list of segments (the target is over sets).
std::vector<std::array<double, 4>> as_set(const SegmentsModel& m) {
  std::vector<std::array<double, 4>> v;
  for (const Line& l : m.scene().lines()) v.push_back({l.seg.a.x, l.seg.a.y, l.seg.b.x, l.seg.b.y});
  std::sort(v.begin(), v.end());
  return v;
}

// A state with some lines fitted to the room (births accepted when they help).
ksmc::runtime::mcmc::Snapshot start_state(const std::shared_ptr<const SharedInput>& sh) {
  SegmentsModel m(sh);
  Rng rng(9);
  for (int i = 0; i < 400; ++i) {
    const double before = m.log_posterior();
    const auto p = (i % 3 == 2 ? segments_test::jitter : segments_test::birth)(m, rng);
    if (p.was_declined()) continue;
    if (m.log_posterior() > before) m.accept();
    else m.reject();
  }
  return m.snapshot();
}

void check_pair(Fn forward, Fn reverse, int cases) {
  const auto sh = segments_test::room_input();
  const auto start = start_state(sh);
  SegmentsModel m(sh), r(sh);
  m.restore(start);
  REQUIRE(m.scene().size() >= 3);
  Rng rng(21);
  int checked = 0;
  for (int c = 0; c < 200 && checked < cases; ++c) {
    m.restore(start);
    const auto before = as_set(m);
    const Proposal p = forward(m, rng);
    if (p.was_declined()) continue;
    REQUIRE(std::isfinite(p.log_q_fwd));
    const auto after_snapshot = m.snapshot();
    m.reject();
    REQUIRE(as_set(m) == before);
    // Reverse from M' until it proposes M.
    bool found = false;
    Rng rr(1000 + static_cast<std::uint64_t>(c));
    for (int t = 0; t < 5000 && !found; ++t) {
      r.restore(after_snapshot);
      const Proposal q = reverse(r, rr);
      if (q.was_declined()) continue;
      const auto back = as_set(r);
      if (back.size() == before.size()) {
        bool same = true;
        for (std::size_t k = 0; k < back.size() && same; ++k)
          for (int d = 0; d < 4; ++d) same = same && std::abs(back[k][static_cast<std::size_t>(d)] - before[k][static_cast<std::size_t>(d)]) < 1e-12;
        if (same) {
          found = true;
          CHECK(q.log_q_fwd == Approx(p.log_q_bwd).epsilon(1e-9).margin(1e-9));
          CHECK(q.log_q_bwd == Approx(p.log_q_fwd).epsilon(1e-9).margin(1e-9));
        }
      }
      r.reject();
    }
    if (found) ++checked;
  }
  CHECK(checked == cases);
}

}  // namespace

TEST_CASE("BIRTH / DEATH densities are consistent", "[segments][kernels]") {
  // BIRTH first: a DEATH from M' can remove exactly the new line (a BIRTH re-drawing a
  // removed line exactly has probability zero, so this direction is the checkable one).
  const auto sh = segments_test::room_input();
  SegmentsModel m(sh);
  m.restore(start_state(sh));
  Rng rng(4);
  int checked = 0;
  for (int c = 0; c < 30; ++c) {
    const auto snap = m.snapshot();
    // BIRTH: M -> M' adding s; DEATH on M' choosing s must report (bwd, fwd) swapped.
    const Proposal b = segments_test::birth(m, rng);
    if (b.was_declined()) continue;
    const auto after = m.snapshot();
    const std::size_t born = m.scene().size() - 1;  // appended last
    const Segment s = m.scene().lines()[born].seg;
    m.reject();
    SegmentsModel r(sh);
    Rng rr(77 + static_cast<std::uint64_t>(c));
    bool found = false;
    for (int t = 0; t < 20000 && !found; ++t) {
      r.restore(after);
      const Proposal d = segments_test::death(r, rr);
      const bool removed_s = std::none_of(r.scene().lines().begin(), r.scene().lines().end(),
                                          [&](const Line& l) { return l.seg == s; });
      if (removed_s) {
        found = true;
        CHECK(d.log_q_fwd == Approx(b.log_q_bwd).epsilon(1e-12));
        CHECK(d.log_q_bwd == Approx(b.log_q_fwd).epsilon(1e-12));
      }
      r.reject();
    }
    CHECK(found);
    ++checked;
    m.restore(snap);
  }
  CHECK(checked >= 20);
}

TEST_CASE("SPLIT / MERGE densities are consistent", "[segments][kernels]") {
  check_pair(segments_test::split, segments_test::merge, 10);
}

TEST_CASE("JITTER is its own reverse with a symmetric density", "[segments][kernels]") {
  const auto sh = segments_test::room_input();
  SegmentsModel m(sh);
  m.restore(start_state(sh));
  Rng rng(8);
  for (int i = 0; i < 200; ++i) {
    const auto ids_before = m.snapshot();
    const Proposal p = segments_test::jitter(m, rng);
    REQUIRE_FALSE(p.was_declined());
    CHECK(p.log_q_fwd == p.log_q_bwd);
    CHECK(m.scene().size() == static_cast<std::size_t>(ids_before.at("lines").size()));
    m.reject();
    CHECK(m.snapshot() == ids_before);
  }
}

namespace {

// The discrete moves (DEATH: which line; MERGE: which pair) are drawn with the probability
// they report: empirical frequencies over many proposals match exp(log_q_fwd) (5 sigma).
void check_discrete_honesty(Fn move) {
  const auto sh = segments_test::room_input();
  SegmentsModel m(sh);
  m.restore(start_state(sh));
  Rng rng(31);
  const int draws = 20000;
  std::map<std::vector<std::array<double, 4>>, std::pair<int, double>> seen;
  for (int i = 0; i < draws; ++i) {
    const Proposal p = move(m, rng);
    REQUIRE_FALSE(p.was_declined());
    auto& e = seen[as_set(m)];
    if (e.first > 0) REQUIRE(e.second == Approx(p.log_q_fwd).epsilon(1e-12));
    ++e.first;
    e.second = p.log_q_fwd;
    m.reject();
  }
  double total = 0.0;
  for (const auto& [state, e] : seen) {
    const double q = std::exp(e.second);
    total += q;
    const double sd = std::sqrt(q * (1.0 - q) / draws);
    CHECK(std::abs(static_cast<double>(e.first) / draws - q) <= 5.0 * sd + 1e-3);
  }
  // Q sums to at most one; outcomes never drawn carry little mass.
  CHECK(total <= 1.0 + 1e-9);
  CHECK(1.0 - total < 10.0 / draws);
}

}  // namespace

TEST_CASE("DEATH draws lines with the probability it reports", "[segments][kernels]") {
  check_discrete_honesty(segments_test::death);
}

TEST_CASE("MERGE draws pairs with the probability it reports", "[segments][kernels]") {
  check_discrete_honesty(segments_test::merge);
}
