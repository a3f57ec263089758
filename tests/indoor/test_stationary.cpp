// End-to-end check of the proposal probabilities: on a tiny discrete world space (subsets of
// three unit candidates, a split line joining them and a door candidate), the MH chain over
// ADD/REMOVE/SPLIT/MERGE/ALLOCATE/DELETE must visit each world with its exact posterior
// probability. Wrong log Q values (or schedule factors) bias these frequencies. A second world
// adds doors that SPLIT and MERGE carry from the units they remove to the units they add.
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

// A nearly flat likelihood so that every state has visible mass.
ScoreParams flat_score() {
  ScoreParams sp;
  for (auto& row : sp.tables[0].p) row = {0.333, 0.333, 0.333};
  sp.tables[0].p[0][0] = sp.tables[0].p[1][1] = sp.tables[0].p[2][2] = 0.3355;
  sp.prior.psi2 = 0.9;
  return sp;
}

// The toy chain: the three unit candidates, the split line of the big unit, `doors`, on `map`.
struct Toy {
  std::vector<CandidateUnit> units{{kBig, 1.0}, {kLeft, 2.0}, {kRight, 0.5}};
  std::vector<CandidateLine> lines{{{12, 0}, {12, 16}, 3.0}};
  std::vector<CandidateDoor> doors;
  ClassGrid map;
  MapEvidence ev;
  KernelSet ks;
  ScoreParams sp = flat_score();

  Toy(const ClassGrid& m, std::vector<CandidateDoor> d)
      : doors(std::move(d)), map(m), ev(map, 0), ks(ev, sources(), kernel_params()) {}

  KernelSources sources() const {
    KernelSources src;
    src.units = [this](const World&) { return std::span<const CandidateUnit>(units); };
    src.split_lines = [this](const World&, const Unit& u) {
      return same_rect(u.rect, kBig) ? lines : std::vector<CandidateLine>{};
    };
    src.doors = [this](const World&) { return std::span<const CandidateDoor>(doors); };
    return src;
  }
  static KernelParams kernel_params() {
    KernelParams kp;
    kp.min_size = 2.0;
    return kp;
  }
  // Adds to m the units of big / left / right whose bit (1, 2, 4) is in mask, ids from `id`;
  // ids[k] is the id given to unit k (0 when absent).
  void add_units(Move& m, int mask, UnitId id, UnitId ids[3]) const {
    for (int k = 0; k < 3; ++k) {
      ids[k] = 0;
      if (!(mask & (1 << k))) continue;
      ids[k] = id;
      m.units.push_back({id, std::nullopt, ev.make_unit(id, k == 0 ? kBig : k == 1 ? kLeft : kRight)});
      ++id;
    }
  }
  // The unnormalised posterior of the world m builds, stored under its label.
  void score(const Move& m, std::string (*label_of)(const World&), std::map<std::string, double>& exact) const {
    ScoredWorld s(map, sp);
    s.apply(m);
    exact[label_of(s.world())] = std::exp(s.log_posterior());
  }
};

void normalise(std::map<std::string, double>& exact) {
  double z = 0.0;
  for (const auto& [k, v] : exact) z += v;
  for (auto& [k, v] : exact) v /= z;
}

struct Visits {
  std::map<std::string, long long> count;
  SamplerStats stats;
};

// Runs MH over ADD/REMOVE/SPLIT/MERGE/ALLOCATE/DELETE from sw's world and checks the visit
// frequencies of the labelled states against `exact`.
Visits check_visits(ScoredWorld& sw, const KernelSet& ks, std::uint64_t seed, const std::map<std::string, double>& exact,
                    std::string (*label_of)(const World&), bool doors_kernels = true) {
  ScheduleStage st;
  st.until = std::numeric_limits<long long>::max();
  st.phi = {0.2, 0.2, 0.15, 0.15, 0.0, 0.0, 0.15, 0.15, 0.0};
  if (!doors_kernels) st.phi = {0.25, 0.25, 0.25, 0.25, 0.0, 0.0, 0.0, 0.0, 0.0};
  DevSampler mh(sw, ks, {st}, seed);
  Visits v;
  const long long n = 400000;
  mh.run(1000);
  for (long long i = 0; i < n; ++i) {
    mh.step();
    ++v.count[label_of(sw.world())];
  }
  for (const auto& [k, p] : exact) {
    const double f = static_cast<double>(v.count[k]) / static_cast<double>(n);
    INFO("state " << k << ": exact " << p << ", sampled " << f);
    CHECK(f == Approx(p).margin(0.015));
  }
  CHECK(static_cast<double>(v.count["other"]) / static_cast<double>(n) < 0.01);
  v.stats = mh.stats();
  return v;
}

// Exact posterior of the ten states of the two-room toy (subsets of big / left / right, the L-R
// door when both halves are there), built with explicit moves.
std::map<std::string, double> ten_states(const Toy& toy) {
  std::map<std::string, double> exact;
  for (int mask = 0; mask < 8; ++mask)
    for (int door = 0; door < 2; ++door) {
      if (door && (mask & 6) != 6) continue;
      Move m;
      UnitId ids[3];
      toy.add_units(m, mask, 1, ids);
      if (door) m.doors.push_back({1, std::nullopt, toy.ev.make_door(1, ids[1], ids[2], {12, 6}, {12, 10})});
      toy.score(m, label, exact);
    }
  normalise(exact);
  return exact;
}

}  // namespace

TEST_CASE("MH over the discrete kernels samples the exact posterior", "[indoor][kernels][stationary]") {
  const Toy toy(draw_plan(16, 24, {{2, 2, 12, 14}, {12, 2, 22, 14}}, 1, {{12, 8}}, 2), {{{12, 6}, {12, 10}, 0.9}});
  const std::map<std::string, double> exact = ten_states(toy);
  REQUIRE(exact.size() == 10);

  ScoredWorld sw(toy.map, toy.sp);
  const Visits v = check_visits(sw, toy.ks, 99, exact, label);
  // Every kernel of the schedule was accepted at least once.
  for (int k : {0, 1, 2, 3, 6, 7}) CHECK(v.stats.accepted[static_cast<std::size_t>(k)] > 0);
}

// The same ten states with seam doors (move.seam_doors) and no ALLOCATE / DELETE: the L-R door
// is made only by a SPLIT that allocates it on its cut and removed only by a MERGE that
// deletes it (REMOVE declines a unit with a door).
TEST_CASE("MH with seam doors on SPLIT / MERGE samples the exact posterior", "[indoor][kernels][stationary]") {
  const Toy toy(draw_plan(16, 24, {{2, 2, 12, 14}, {12, 2, 22, 14}}, 1, {{12, 8}}, 2), {{{12, 6}, {12, 10}, 0.9}});
  const std::map<std::string, double> exact = ten_states(toy);
  KernelSources src = toy.sources();
  src.seam_doors = [&toy](const OrientedRect& a, const OrientedRect& b) {
    const bool halves = (same_rect(a, kLeft) && same_rect(b, kRight)) || (same_rect(a, kRight) && same_rect(b, kLeft));
    return halves ? toy.doors : std::vector<CandidateDoor>{};
  };
  const KernelSet ks(toy.ev, src, Toy::kernel_params());
  ScoredWorld sw(toy.map, toy.sp);
  const Visits v = check_visits(sw, ks, 5, exact, label, false);
  CHECK(v.stats.accepted[2] > 0);
  CHECK(v.stats.accepted[3] > 0);
  CHECK(v.count.at("-LR+door") > 0);
}

namespace {

const OrientedRect kBottom{12, 17, 20, 6, 0.0};  // [2,22] x [14,20], always present

// Like label(), plus which unit the door under the left half of y = 14 joins to the bottom unit
// ("L" through the left unit, "B" through the big one) and whether the L-R door is there.
std::string carry_label(const World& w) {
  const Unit* bottom = nullptr;
  std::vector<Unit> rest;
  for (const Unit& u : w.units()) {
    if (same_rect(u.rect, kBottom) && !bottom) bottom = &u;
    else rest.push_back(u);
  }
  if (!bottom) return "other";
  World others;
  Move m;
  for (const Unit& u : rest) m.units.push_back({u.id, std::nullopt, u});
  others.apply(m);
  std::string s = label(others);
  if (s == "other") return s;
  std::string lr, bd;
  for (const Door& d : w.doors()) {
    if (d.a.y != 14.0) {
      lr = "+lr";
      continue;
    }
    const UnitId upper = d.unit_a == bottom->id ? d.unit_b : d.unit_a;
    bd = same_rect(w.find_unit(upper)->rect, kBig) ? "+dB" : "+dL";
  }
  return s + lr + bd;
}

}  // namespace

// The same check with doors that SPLIT and MERGE must carry: a fixed bottom unit below big /
// left / right and a door candidate on the wall between the bottom unit and the left half. A
// SPLIT of the big unit moves that door to the left half, a MERGE of left and right moves it
// to the big unit; the exact posterior is over every world those doors can be in.
TEST_CASE("MH with doors carried by SPLIT / MERGE samples the exact posterior", "[indoor][kernels][stationary]") {
  const Toy toy(draw_plan(22, 24, {{2, 2, 12, 14}, {12, 2, 22, 14}, {2, 14, 22, 20}}, 1, {{12, 8}, {7, 14}}, 2),
                {{{12, 6}, {12, 10}, 0.9}, {{5, 14}, {9, 14}, 0.7}});
  // Every world: a subset of big / left / right, the L-R door when both halves are there, the
  // bottom door absent or joined to the big or the left unit when that unit is there.
  std::map<std::string, double> exact;
  for (int mask = 0; mask < 8; ++mask)
    for (int lr = 0; lr < 2; ++lr)
      for (int bd = 0; bd < 3; ++bd) {  // 0 none, 1 through big, 2 through left
        if ((lr && (mask & 6) != 6) || (bd == 1 && !(mask & 1)) || (bd == 2 && !(mask & 2))) continue;
        Move m;
        m.units.push_back({1, std::nullopt, toy.ev.make_unit(1, kBottom)});
        UnitId ids[3];
        toy.add_units(m, mask, 2, ids);
        if (lr) m.doors.push_back({1, std::nullopt, toy.ev.make_door(1, ids[1], ids[2], {12, 6}, {12, 10})});
        if (bd) m.doors.push_back({2, std::nullopt, toy.ev.make_door(2, 1, ids[bd == 1 ? 0 : 1], {5, 14}, {9, 14})});
        toy.score(m, carry_label, exact);
      }
  normalise(exact);
  REQUIRE(exact.size() == 21);

  ScoredWorld sw(toy.map, toy.sp);
  Move start;
  start.units.push_back({1, std::nullopt, toy.ev.make_unit(1, kBottom)});
  sw.apply(start);
  const Visits v = check_visits(sw, toy.ks, 7, exact, carry_label);
  // SPLIT and MERGE were accepted, and the carried door was seen on both units.
  CHECK(v.stats.accepted[2] > 0);
  CHECK(v.stats.accepted[3] > 0);
  CHECK(v.count.at("B--+dB") > 0);
  CHECK(v.count.at("-LR+dL") + v.count.at("-LR+lr+dL") > 0);
}
