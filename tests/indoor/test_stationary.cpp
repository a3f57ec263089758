// End-to-end check of the proposal probabilities: on a tiny discrete world space (subsets of
// three unit candidates, a split line joining them and a door candidate), the MH chain over
// ADD/REMOVE/SPLIT/MERGE/ALLOCATE/DELETE must visit each world with its exact posterior
// probability. Wrong log Q values (or schedule factors) bias these frequencies.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "stdlib/indoor/dev_sampler.h"
#include "tests/indoor/synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor;

namespace {

const OrientedRect kBig{12, 8, 20, 12, 0.0};   // [2,22] x [2,14]
const OrientedRect kLeft{7, 8, 10, 12, 0.0};   // [2,12] x [2,14]
const OrientedRect kRight{17, 8, 10, 12, 0.0}; // [12,22] x [2,14]

// State label: which of big/left/right are present (once), whether the door is, or "other".
std::string label(const World& w) {
  int n[3] = {0, 0, 0};
  for (const Unit& u : w.units()) {
    if (same_rect(u.rect, kBig)) ++n[0];
    else if (same_rect(u.rect, kLeft)) ++n[1];
    else if (same_rect(u.rect, kRight)) ++n[2];
    else return "other";
  }
  if (n[0] > 1 || n[1] > 1 || n[2] > 1) return "other";
  std::string s;
  s += n[0] ? 'B' : '-';
  s += n[1] ? 'L' : '-';
  s += n[2] ? 'R' : '-';
  s += w.doors().empty() ? "" : "+door";
  return s;
}

}  // namespace

TEST_CASE("MH over the discrete kernels samples the exact posterior", "[indoor][kernels][stationary]") {
  const ClassGrid map = draw_plan(16, 24, {{2, 2, 12, 14}, {12, 2, 22, 14}}, 1, {{12, 8}}, 2);
  const MapEvidence ev(map, 0);
  const std::vector<CandidateUnit> units{{kBig, 1.0}, {kLeft, 2.0}, {kRight, 0.5}};
  const std::vector<CandidateLine> lines{{{12, 0}, {12, 16}, 3.0}};
  const std::vector<CandidateDoor> doors{{{12, 6}, {12, 10}, 0.9}};
  KernelSources src;
  src.units = [&](const World&) { return std::span<const CandidateUnit>(units); };
  src.split_lines = [&](const World&, const Unit& u) {
    return same_rect(u.rect, kBig) ? lines : std::vector<CandidateLine>{};
  };
  src.doors = [&](const World&) { return std::span<const CandidateDoor>(doors); };
  KernelParams kp;
  kp.min_size = 2.0;
  const KernelSet ks(ev, src, kp);

  // A nearly flat likelihood so that every state has visible mass.
  ScoreParams sp;
  for (auto& row : sp.tables[0].p) row = {0.333, 0.333, 0.333};
  sp.tables[0].p[0][0] = sp.tables[0].p[1][1] = sp.tables[0].p[2][2] = 0.3355;
  sp.prior.psi2 = 0.9;

  // Exact posterior of the ten states, built with explicit moves.
  std::map<std::string, double> exact;
  {
    double z = 0.0;
    for (int mask = 0; mask < 8; ++mask)
      for (int door = 0; door < 2; ++door) {
        if (door && (mask & 6) != 6) continue;
        ScoredWorld s(map, sp);
        Move m;
        UnitId id = 1;
        UnitId left = 0, right = 0;
        for (int k = 0; k < 3; ++k) {
          if (!(mask & (1 << k))) continue;
          const OrientedRect r = k == 0 ? kBig : k == 1 ? kLeft : kRight;
          if (k == 1) left = id;
          if (k == 2) right = id;
          m.units.push_back({id, std::nullopt, ev.make_unit(id, r)});
          ++id;
        }
        if (door) m.doors.push_back({1, std::nullopt, ev.make_door(1, left, right, {12, 6}, {12, 10})});
        s.apply(m);
        const double p = std::exp(s.log_posterior());
        exact[label(s.world())] = p;
        z += p;
      }
    for (auto& [k, v] : exact) v /= z;
  }
  REQUIRE(exact.size() == 10);

  ScheduleStage st;
  st.until = std::numeric_limits<long long>::max();
  st.phi = {0.2, 0.2, 0.15, 0.15, 0.0, 0.0, 0.15, 0.15, 0.0};
  ScoredWorld sw(map, sp);
  DevSampler mh(sw, ks, {st}, 99);
  std::map<std::string, long long> visits;
  const long long n = 400000;
  mh.run(1000);
  for (long long i = 0; i < n; ++i) {
    mh.step();
    ++visits[label(sw.world())];
  }
  for (const auto& [k, p] : exact) {
    const double f = static_cast<double>(visits[k]) / static_cast<double>(n);
    INFO("state " << k << ": exact " << p << ", sampled " << f);
    CHECK(f == Approx(p).margin(0.015));
  }
  CHECK(static_cast<double>(visits["other"]) / static_cast<double>(n) < 0.01);
  // Every kernel of the schedule was accepted at least once.
  for (int k : {0, 1, 2, 3, 6, 7}) CHECK(mh.stats().accepted[static_cast<std::size_t>(k)] > 0);
}
