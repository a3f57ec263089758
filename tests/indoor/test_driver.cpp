// Development driver: an MH loop (DevSampler, Table 3.2 schedule) over all nine kernels on a
// synthetic plan of four rooms and a corridor, from an empty world; the cell prediction rate
// K(W,M) (eq. 3.39) must exceed 0.9 and the incremental score must still match a full rescore.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "stdlib/indoor/dev_sampler.h"
#include "tests/indoor/synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor;

namespace {

struct Plan {
  std::vector<Room> rooms{{10, 10, 60, 50}, {60, 10, 100, 50}, {100, 10, 150, 50},
                          {10, 50, 150, 66}, {40, 66, 100, 100}};
  std::vector<cv::Point> doors{{35, 50}, {80, 50}, {125, 50}, {70, 66}, {60, 30}};
  ClassGrid map = draw_plan(110, 160, rooms, 2, doors, 5);
};

// WBU-like stand-in: every rectangle on the plan's wall lines, weighted by eq. 3.10, plus
// copies shifted by a few cells (which SHRINK/DILATE must repair).
std::vector<CandidateUnit> unit_candidates(const MapEvidence& ev) {
  const std::vector<double> xs{10, 40, 60, 100, 150}, ys{10, 50, 66, 100};
  std::vector<CandidateUnit> out;
  auto add = [&](double x0, double x1, double y0, double y1) {
    const OrientedRect r{0.5 * (x0 + x1), 0.5 * (y0 + y1), x1 - x0, y1 - y0, 0.0};
    const auto w = ev.wall_weights(r);
    out.push_back({r, std::max(*std::min_element(w.begin(), w.end()), 0.01)});
  };
  for (std::size_t a = 0; a < xs.size(); ++a)
    for (std::size_t b = a + 1; b < xs.size(); ++b)
      for (std::size_t c = 0; c < ys.size(); ++c)
        for (std::size_t d = c + 1; d < ys.size(); ++d) {
          add(xs[a], xs[b], ys[c], ys[d]);
          add(xs[a] + 3, xs[b] - 2, ys[c] + 2, ys[d] + 3);
        }
  return out;
}

}  // namespace

TEST_CASE("MH over the nine kernels explains a synthetic plan (K > 0.9)", "[indoor][driver]") {
  Plan plan;
  MapEvidence ev(plan.map, 1);
  const auto cands = unit_candidates(ev);
  const std::vector<CandidateLine> lines{{{60, 8}, {60, 52}, 0}, {{100, 8}, {100, 52}, 0},
                                         {{8, 50}, {152, 50}, 0}, {{8, 66}, {152, 66}, 0}};
  const std::vector<CandidateDoor> doors{{{33, 50}, {37, 50}, 0.9}, {{78, 50}, {82, 50}, 0.9},
                                         {{123, 50}, {127, 50}, 0.9}, {{68, 66}, {72, 66}, 0.9},
                                         {{60, 28}, {60, 32}, 0.9}};
  KernelSources src;
  src.units = [&](const World&) { return std::span<const CandidateUnit>(cands); };
  src.split_lines = [&](const World&, const Unit& u) {
    std::vector<CandidateLine> out;
    const Box b = own_box(u.rect);
    for (const auto& l : lines) {
      const Point2 m{0.5 * (l.a.x + l.b.x), 0.5 * (l.a.y + l.b.y)};
      const bool vertical = std::abs(l.a.x - l.b.x) < 1e-9;
      const bool inside = vertical ? (m.x > b.x0 && m.x < b.x1) : (m.y > b.y0 && m.y < b.y1);
      if (inside) out.push_back(l);
    }
    return out;
  };
  src.doors = [&](const World&) { return std::span<const CandidateDoor>(doors); };
  KernelParams kp;
  kp.min_size = 4.0;
  KernelSet ks(ev, src, kp);

  ScoreParams sp;
  sp.raster.wall_thickness = 1.0;
  ScoredWorld sw(plan.map, sp);
  const double k0 = sw.cell_prediction_rate();
  DevSampler mh(sw, ks, schedule_table_3_2(), 2024);
  mh.run(6000);

  std::cout << "driver: K(W,M) " << k0 << " -> " << sw.cell_prediction_rate() << ", units "
            << sw.world().units().size() << ", doors " << sw.world().doors().size() << "\n";
  for (int k = 0; k < kKernelKinds; ++k)
    std::cout << "  " << kernel_name(static_cast<KernelKind>(k)) << ": proposed "
              << mh.stats().proposed[static_cast<std::size_t>(k)] << " accepted "
              << mh.stats().accepted[static_cast<std::size_t>(k)] << " declined "
              << mh.stats().declined[static_cast<std::size_t>(k)] << "\n";
  CHECK(sw.cell_prediction_rate() > 0.9);
  CHECK(k0 < 0.6);
  CHECK(sw.log_likelihood() == Approx(sw.recompute_log_likelihood()).epsilon(1e-9));
  CHECK(sw.log_prior() == Approx(sw.recompute_log_prior()).epsilon(1e-9));
  CHECK(mh.best_log_posterior() >= sw.log_posterior());
  // Several kernel kinds took part.
  int kinds_accepted = 0;
  for (auto a : mh.stats().accepted) kinds_accepted += a > 0 ? 1 : 0;
  CHECK(kinds_accepted >= 4);

  // Same seed, same result.
  ScoredWorld sw2(plan.map, sp);
  DevSampler mh2(sw2, ks, schedule_table_3_2(), 2024);
  mh2.run(6000);
  CHECK(sw2.log_posterior() == sw.log_posterior());
  REQUIRE(sw2.world().units().size() == sw.world().units().size());
}

TEST_CASE("along an MH run every kernel's sampling path matches its own log_q", "[indoor][driver]") {
  Plan plan;
  MapEvidence ev(plan.map, 1);
  const auto cands = unit_candidates(ev);
  const std::vector<CandidateLine> lines{{{60, 8}, {60, 52}, 0}, {{100, 8}, {100, 52}, 0},
                                         {{8, 50}, {152, 50}, 0}, {{40, 40}, {40, 90}, 2}};
  const std::vector<CandidateDoor> doors{{{33, 50}, {37, 50}, 0.9}, {{78, 50}, {82, 50}, 0.9},
                                         {{60, 28}, {60, 32}, 0.9}};
  KernelSources src;
  src.units = [&](const World&) { return std::span<const CandidateUnit>(cands); };
  src.split_lines = [&](const World&, const Unit&) { return lines; };
  src.doors = [&](const World&) { return std::span<const CandidateDoor>(doors); };
  KernelParams kp;
  kp.min_size = 4.0;
  kp.orientation.enabled = true;
  KernelSet ks(ev, src, kp);
  ScoreParams sp;
  ScoredWorld sw(plan.map, sp);
  DevSampler mh(sw, ks, schedule_table_3_2(), 5);
  Rng rng(77);
  std::array<int, kKernelKinds> checked{};
  for (int round = 0; round < 60; ++round) {
    mh.run(100);
    const World w = sw.world();
    for (int k = 0; k < kKernelKinds; ++k) {
      const auto kind = static_cast<KernelKind>(k);
      for (int t = 0; t < 5; ++t) {
        const auto p = ks.propose(kind, w, rng);
        if (!p) continue;
        ++checked[static_cast<std::size_t>(k)];
        INFO(kernel_name(kind) << " at iteration " << (round + 1) * 100);
        REQUIRE(std::isfinite(p->log_q_fwd));
        REQUIRE(ks.log_q(kind, w, p->move) == Approx(p->log_q_fwd).epsilon(1e-12));
        // The inverse move brings the proposed world back, and the scored state agrees.
        const World next = w.applied(p->move);
        const World back = next.applied(p->move.inverse());
        REQUIRE(back.units().size() == w.units().size());
        const double before = sw.log_posterior();
        sw.apply(p->move);
        sw.revert(p->move);
        REQUIRE(sw.log_posterior() == before);
      }
    }
  }
  for (int k = 0; k < kKernelKinds; ++k) {
    INFO(kernel_name(static_cast<KernelKind>(k)));
    CHECK(checked[static_cast<std::size_t>(k)] > 0);
  }
}
