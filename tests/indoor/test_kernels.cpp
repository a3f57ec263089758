// The five reversible kernel pairs: a forward proposal, its reverse proposed by the reverse
// kernel on the proposed world, and the consistency of their log Q values (§3.5.3); plus the
// empirical frequency of discrete proposals against exp(log_q_fwd).
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/kernels.h"
#include "tests/indoor/kernel_fixture.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::tests::indoor;

namespace {

KernelParams params() {
  KernelParams p;
  p.min_size = 3.0;
  return p;
}

// Same change up to unit ids: rects removed / added / modified and door segments match.
bool equivalent(const Move& a, const Move& b) {
  if (a.kind != b.kind || a.units.size() != b.units.size() || a.doors.size() != b.doors.size()) return false;
  std::vector<bool> used(b.units.size(), false);
  for (const auto& x : a.units) {
    bool found = false;
    for (std::size_t i = 0; i < b.units.size() && !found; ++i) {
      const auto& y = b.units[i];
      if (used[i] || x.before.has_value() != y.before.has_value() || x.after.has_value() != y.after.has_value())
        continue;
      if (x.before && !same_rect(x.before->rect, y.before->rect, 1e-6)) continue;
      if (x.after && !same_rect(x.after->rect, y.after->rect, 1e-6)) continue;
      used[i] = found = true;
    }
    if (!found) return false;
  }
  for (std::size_t i = 0; i < a.doors.size(); ++i) {
    const auto& x = a.doors[i];
    const auto& y = b.doors[i];
    const auto& dx = x.before ? *x.before : *x.after;
    const auto& dy = y.before ? *y.before : *y.after;
    if (distance(dx.a, dy.a) > 1e-6 || distance(dx.b, dy.b) > 1e-6) return false;
  }
  return true;
}

// First proposal (over seeds) accepted by `want` with a finite reverse probability.
std::optional<Proposal> find(const KernelSet& ks, KernelKind k, const World& w,
                             const std::function<bool(const Proposal&)>& want, int tries = 5000) {
  for (int seed = 0; seed < tries; ++seed) {
    Rng rng(static_cast<std::uint64_t>(seed) * 7919u + 1u);
    auto p = ks.propose(k, w, rng);
    if (p && std::isfinite(p->log_q_bwd) && want(*p)) return p;
  }
  return std::nullopt;
}

// The reverse kernel proposes the inverse on W' (found by sampling) and the log Q values agree.
void check_round_trip(const KernelSet& ks, KernelKind k, const World& w,
                      const std::function<bool(const Proposal&)>& want = [](const Proposal&) { return true; }) {
  INFO("kernel " << kernel_name(k));
  const auto p = find(ks, k, w, want);
  REQUIRE(p);
  CHECK(std::isfinite(p->log_q_fwd));
  // The sampling path's probability equals the kernel's evaluation of the same move.
  CHECK(ks.log_q(k, w, p->move) == Approx(p->log_q_fwd).epsilon(1e-12));
  const World next = w.applied(p->move);
  const Move inv = p->move.inverse();
  const auto r = find(ks, reverse_of(k), next, [&](const Proposal& q) { return equivalent(q.move, inv); });
  REQUIRE(r);
  CHECK(r->log_q_fwd == Approx(p->log_q_bwd).epsilon(1e-9));
  CHECK(r->log_q_bwd == Approx(p->log_q_fwd).epsilon(1e-9));
  // Applying the reverse restores the original geometry.
  const World back = next.applied(r->move);
  REQUIRE(back.units().size() == w.units().size());
  for (const Unit& u : w.units()) {
    bool found = false;
    for (const Unit& v : back.units()) found = found || same_rect(u.rect, v.rect, 1e-6);
    CHECK(found);
  }
  CHECK(back.doors().size() == w.doors().size());
}

// For continuous kernels: the reverse kernel's score of the exact inverse move.
void check_inverse_scored(const KernelSet& ks, KernelKind k, const World& w,
                          const std::function<bool(const Proposal&)>& want = [](const Proposal&) { return true; }) {
  INFO("kernel " << kernel_name(k));
  const auto p = find(ks, k, w, want);
  REQUIRE(p);
  CHECK(ks.log_q(k, w, p->move) == Approx(p->log_q_fwd).epsilon(1e-12));
  const World next = w.applied(p->move);
  const Move inv = p->move.inverse();
  CHECK(ks.log_q(reverse_of(k), next, inv) == Approx(p->log_q_bwd).epsilon(1e-12));
  // Reverse of the reverse on the original world is the forward move again.
  CHECK(ks.log_q(k, w, inv.inverse()) == Approx(p->log_q_fwd).epsilon(1e-12));
  const World back = next.applied(inv);
  for (const Unit& u : w.units()) CHECK(same_rect(u.rect, back.find_unit(u.id)->rect, 1e-9));
}

// A+B (unit 1, y in [10, 40]) over the corridor D (unit 2), joined by the A-D door on y = 40.
World a_b_over_d_with_door(const KernelFixture& fx) {
  World w = world_of({fx.unit(1, {10, 10, 80, 40}), fx.unit(2, fx.rooms[3])});
  Move door;
  door.doors.push_back({1, std::nullopt, fx.evidence.make_door(1, 1, 2, {27, 40}, {33, 40})});
  w.apply(door);
  return w;
}

}  // namespace

TEST_CASE("ADD / REMOVE round trip and proposal frequencies", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  const World w = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[3])});
  check_round_trip(ks, KernelKind::Add, w);
  check_round_trip(ks, KernelKind::Remove, w);

  // Empirical frequencies of REMOVE choices match exp(log_q_fwd).
  const World w3 = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[1]), fx.unit(3, fx.rooms[3]),
                             fx.evidence.make_unit(4, OrientedRect{60, 30, 30, 20, 0.3})});
  std::map<UnitId, int> count;
  std::map<UnitId, double> prob;
  Rng rng(7);
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    auto p = ks.propose(KernelKind::Remove, w3, rng);
    REQUIRE(p);
    ++count[p->move.units[0].id];
    prob[p->move.units[0].id] = std::exp(p->log_q_fwd);
  }
  double total = 0.0;
  for (const auto& [id, pr] : prob) {
    total += pr;
    CHECK(static_cast<double>(count[id]) / n == Approx(pr).margin(0.015));
  }
  CHECK(total == Approx(1.0).epsilon(1e-9));
  // The badly matching rotated unit is the likeliest to be removed (b_r, eq. 3.21).
  CHECK(prob[4] > prob[1]);
}

// move.uniform_rect: ADD draws a share of its proposals uniformly over rectangles, so REMOVE
// has a reverse for a unit no detector proposes (here a shrunk room); without it that REMOVE
// is always rejected.
TEST_CASE("ADD's uniform share gives REMOVE a reverse for every unit", "[indoor][kernels]") {
  KernelFixture fx;
  KernelParams p0 = params();
  KernelParams p1 = params();
  p1.uniform_share = 0.05;
  KernelSet detectors_only(fx.evidence, fx.sources(), p0), mixed(fx.evidence, fx.sources(), p1);
  const World w = world_of({fx.evidence.make_unit(1, OrientedRect{30, 25, 36, 26, 0.0}), fx.unit(2, fx.rooms[3])});
  const double diag = std::hypot(64.0, 120.0);
  const double log_uniform = std::log(0.05) - std::log(0.5 * std::numbers::pi) - std::log(64.0 * 120.0) - 2.0 * std::log(diag - 3.0);
  Move remove;
  remove.kind = KernelKind::Remove;
  remove.units.push_back({1, *w.find_unit(1), std::nullopt});
  const World after = w.applied(remove);
  const Move add = remove.inverse();
  CHECK(detectors_only.log_q(KernelKind::Add, after, add) == -std::numeric_limits<double>::infinity());
  CHECK(mixed.log_q(KernelKind::Add, after, add) == Approx(log_uniform).epsilon(1e-12));
  // A quarter turn with the sides swapped, or a negative angle, is the same rectangle.
  for (const OrientedRect r : {OrientedRect{30, 25, 26, 36, 0.5 * std::numbers::pi}, OrientedRect{30, 25, 26, 36, -0.5 * std::numbers::pi},
                               OrientedRect{30, 25, 36, 26, std::numbers::pi}}) {
    Move a = add;
    a.units[0].after = fx.evidence.make_unit(a.units[0].id, r);
    CHECK(mixed.log_q(KernelKind::Add, after, a) == Approx(log_uniform).epsilon(1e-12));
  }
  // Outside the support (centre off the map, a side under min_size): no density.
  for (const OrientedRect r : {OrientedRect{-1, 25, 36, 26, 0.0}, OrientedRect{30, 25, 2, 26, 0.0}}) {
    Move a = add;
    a.units[0].after = fx.evidence.make_unit(a.units[0].id, r);
    CHECK(mixed.log_q(KernelKind::Add, after, a) == -std::numeric_limits<double>::infinity());
  }
  // A candidate keeps its normalised weight, times 1 - share.
  Move add_room = add;
  add_room.units[0].after = fx.unit(add.units[0].id, fx.rooms[0]);
  CHECK(mixed.log_q(KernelKind::Add, after, add_room) ==
        Approx(std::log(0.95) + detectors_only.log_q(KernelKind::Add, after, add_room)).epsilon(1e-12));
  // The sampled REMOVE carries that reverse; the uniform ADDs are scored as they are drawn.
  const auto r = find(mixed, KernelKind::Remove, w, [](const Proposal& q) { return q.move.units[0].id == 1; });
  REQUIRE(r);
  CHECK(r->log_q_bwd == Approx(log_uniform).epsilon(1e-12));
  check_inverse_scored(mixed, KernelKind::Add, after, [&](const Proposal& q) {
    return detectors_only.log_q(KernelKind::Add, after, q.move) == -std::numeric_limits<double>::infinity();
  });
  // About 5 % of ADD proposals are uniform draws.
  Rng rng(11);
  int uniform = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const auto q = mixed.propose(KernelKind::Add, after, rng);
    REQUIRE(q);
    uniform += detectors_only.log_q(KernelKind::Add, after, q->move) == -std::numeric_limits<double>::infinity();
  }
  CHECK(static_cast<double>(uniform) / n == Approx(0.05).margin(0.005));
}

TEST_CASE("SPLIT / MERGE round trip", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  // A+B as one unit: SPLIT along x = 50 (the tilted line snaps to a perpendicular cut).
  const World w = world_of({fx.unit(1, {10, 10, 80, 40}), fx.unit(2, fx.rooms[3])});
  check_round_trip(ks, KernelKind::Split, w, [](const Proposal& p) { return p.move.units[0].id == 1; });
  // MERGE of two exact halves whose boundary is a detected line (x = 80).
  const World w2 = world_of({fx.unit(1, fx.rooms[1]), fx.unit(2, fx.rooms[2]), fx.unit(3, fx.rooms[3])});
  check_round_trip(ks, KernelKind::Merge, w2, [](const Proposal& p) { return p.move.units[0].id != 3; });
  // A + B tile a rectangle, but the only line near x = 50 is tilted and cuts at x = 50.25, so
  // SPLIT cannot undo that merge: its reverse probability is zero (the move is always rejected).
  const World w3 = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[1]), fx.unit(3, fx.rooms[3])});
  Rng rng(3);
  int merges = 0;
  for (int i = 0; i < 300; ++i) {
    auto p = ks.propose(KernelKind::Merge, w3, rng);
    if (!p) continue;
    ++merges;
    CHECK(std::isfinite(p->log_q_fwd));
    CHECK(p->log_q_bwd == -std::numeric_limits<double>::infinity());
  }
  CHECK(merges > 0);
}

TEST_CASE("SPLIT / MERGE carry the doors of the units they replace", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  const World w = a_b_over_d_with_door(fx);
  // SPLIT near x = 50: the door goes to the A half, the only one with a wall under it.
  auto at_a = [](const Proposal& p) {
    if (p.move.units[0].id != 1 || p.move.units[1].after->rect.cx > 45.0) return false;
    return p.move.doors.size() == 1 && p.move.doors[0].after->unit_a == 2 &&
           p.move.doors[0].after->unit_b == p.move.units[1].id;
  };
  check_round_trip(ks, KernelKind::Split, w, [](const Proposal& p) { return p.move.units[0].id == 1; });
  const auto p = find(ks, KernelKind::Split, w, at_a);
  REQUIRE(p);
  CHECK(ks.log_q(KernelKind::Split, w, p->move) == Approx(p->log_q_fwd).epsilon(1e-12));
  // The same unit change with the door left on the wrong half is not a SPLIT move.
  Move wrong = p->move;
  wrong.doors[0].after->unit_b = p->move.units[2].id;
  CHECK(ks.log_q(KernelKind::Split, w, wrong) == -std::numeric_limits<double>::infinity());
  // MERGE of the two halves (one with the door) is SPLIT's reverse, door included.
  const World halves = w.applied(p->move);
  check_round_trip(ks, KernelKind::Merge, halves, [](const Proposal& q) { return q.move.units[0].id != 2; });
  // A door between the two units of a MERGE cannot be carried (no SPLIT makes one): declined.
  World ab = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[1]), fx.unit(3, fx.rooms[3])});
  Move ab_door;
  ab_door.doors.push_back({1, std::nullopt, fx.evidence.make_door(1, 1, 2, {50, 22}, {50, 28})});
  ab.apply(ab_door);
  Rng rng(5);
  for (int i = 0; i < 300; ++i) {
    auto q = ks.propose(KernelKind::Merge, ab, rng);
    if (q) CHECK(q->move.units[0].id + q->move.units[1].id != 3);
  }
}

// move.seam_doors: SPLIT allocates door candidates on its cut (each with probability 1/2),
// MERGE deletes the doors joining its two units; without the source neither happens.
TEST_CASE("SPLIT allocates the doors on its cut and MERGE deletes them (seam doors)", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSources src = fx.sources();
  src.seam_doors = [&fx](const OrientedRect& a, const OrientedRect& b) {
    detect::DoorParams dp;
    dp.min_door = 2.0;
    return to_door_candidates(detect::detect_doors(fx.map, {a, b}, dp));
  };
  KernelSet ks(fx.evidence, src, params()), plain(fx.evidence, fx.sources(), params());
  // A + B over D, no door: a SPLIT near x = 50 finds the A-B doorway on its cut.
  const World w = world_of({fx.unit(1, {10, 10, 80, 40}), fx.unit(2, fx.rooms[3])});
  auto near_50 = [](const Proposal& p) {
    return p.move.units[0].id == 1 && std::abs(std::min(p.move.units[1].after->rect.cx, p.move.units[2].after->rect.cx) - 30.0) < 1.0;
  };
  const auto with_door = [&](const Proposal& p) { return near_50(p) && p.move.doors.size() == 1; };
  const auto without = [&](const Proposal& p) { return near_50(p) && p.move.doors.empty(); };
  check_round_trip(ks, KernelKind::Split, w, with_door);
  check_round_trip(ks, KernelKind::Split, w, without);
  const auto p = find(ks, KernelKind::Split, w, with_door);
  REQUIRE(p);
  const Door& d = *p->move.doors[0].after;
  CHECK(std::abs(0.5 * (d.a.x + d.b.x) - 50.0) < 1.5);  // on the cut
  CHECK(std::abs(0.5 * (d.a.y + d.b.y) - 25.0) < 3.0);  // at the doorway
  // The cut's unit change alone is the plain SPLIT's, times 1/2 for the one candidate.
  Move bare = p->move;
  bare.doors.clear();
  CHECK(ks.log_q(KernelKind::Split, w, bare) == Approx(plain.log_q(KernelKind::Split, w, bare) + std::log(0.5)).epsilon(1e-12));
  CHECK(plain.log_q(KernelKind::Split, w, p->move) == -std::numeric_limits<double>::infinity());
  // A door the detector does not give on the cut is not a SPLIT move.
  Move moved = p->move;
  moved.doors[0].after->a.y += 5.0;
  moved.doors[0].after->b.y += 5.0;
  CHECK(ks.log_q(KernelKind::Split, w, moved) == -std::numeric_limits<double>::infinity());
  // MERGE of the two halves deletes their door; the plain MERGE declines such a pair.
  const World halves = w.applied(p->move);
  REQUIRE(halves.doors().size() == 1);
  check_round_trip(ks, KernelKind::Merge, halves, [](const Proposal& q) { return q.move.units[0].id != 2 && q.move.units[1].id != 2; });
  Rng rng(3);
  for (int i = 0; i < 300; ++i) {
    auto q = plain.propose(KernelKind::Merge, halves, rng);
    if (q) CHECK((q->move.units[0].id == 2 || q->move.units[1].id == 2));
  }
}

TEST_CASE("SHRINK / DILATE inverse moves are scored consistently", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  const World w = world_of({fx.unit(1, {12, 12, 47, 37}), fx.unit(2, fx.rooms[3]),
                            fx.evidence.make_unit(3, OrientedRect{95, 25, 20, 16, 0.4})});
  check_inverse_scored(ks, KernelKind::Shrink, w);
  check_inverse_scored(ks, KernelKind::Dilate, w);
  check_inverse_scored(ks, KernelKind::Dilate, w, [](const Proposal& p) { return p.move.units[0].id == 3; });
  // SHRINK only shrinks, DILATE only grows.
  Rng rng(5);
  for (int i = 0; i < 200; ++i) {
    auto s = ks.propose(KernelKind::Shrink, w, rng);
    if (s) CHECK(s->move.units[0].after->rect.area() < s->move.units[0].before->rect.area());
    auto d = ks.propose(KernelKind::Dilate, w, rng);
    if (d) CHECK(d->move.units[0].after->rect.area() > d->move.units[0].before->rect.area());
  }
}

// A unit with a door may change shape when the door stays on one of its walls (within
// door_snap); before, it was frozen for SHRINK / DILATE.
TEST_CASE("SHRINK / DILATE change a unit with doors that stay on its walls", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  const World w = a_b_over_d_with_door(fx);
  const auto on_unit_1 = [](const Proposal& p) { return p.move.units[0].id == 1; };
  check_inverse_scored(ks, KernelKind::Shrink, w, on_unit_1);
  check_inverse_scored(ks, KernelKind::Dilate, w, on_unit_1);
  // Every proposal on unit 1 keeps the door's wall (y = 40, wall 2) within door_snap.
  Rng rng(3);
  int seen = 0;
  for (int i = 0; i < 400; ++i)
    for (KernelKind k : {KernelKind::Shrink, KernelKind::Dilate}) {
      const auto p = ks.propose(k, w, rng);
      if (!p || p->move.units[0].id != 1) continue;
      ++seen;
      const OrientedRect& r = p->move.units[0].after->rect;
      CHECK(std::abs(r.cy + 0.5 * r.h - 40.0) <= params().door_snap + 1e-9);
      CHECK(p->move.doors.empty());
    }
  CHECK(seen > 0);
  // The door's wall moved by 1.5 cells is a DILATE move; by 3 cells (the door left behind) not.
  const Unit& u = *w.find_unit(1);
  for (const double delta : {1.5, 3.0}) {
    Move m;
    m.kind = KernelKind::Dilate;
    m.units.push_back({1, u, fx.evidence.make_unit(1, OrientedRect{45, 25 + 0.5 * delta, 70, 30 + delta, 0.0})});
    m.detail.wall = 2;
    m.detail.delta = delta;
    CHECK(std::isfinite(ks.log_q(KernelKind::Dilate, w, m)) == (delta < 2.0));
  }
}

TEST_CASE("ALLOCATE / DELETE round trip", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  World w = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[1]), fx.unit(3, fx.rooms[2]),
                      fx.unit(4, fx.rooms[3])});
  check_round_trip(ks, KernelKind::Allocate, w);
  // The A-B door attaches to units 1 and 2.
  const auto p = find(ks, KernelKind::Allocate, w, [](const Proposal& q) {
    return std::abs(q.move.doors[0].after->a.x - 50.0) < 1e-9;
  });
  REQUIRE(p);
  CHECK(p->move.doors[0].after->unit_a == 1);
  CHECK(p->move.doors[0].after->unit_b == 2);
  w.apply(p->move);
  check_round_trip(ks, KernelKind::Delete, w);
  // A unit with a door is locked against structural moves.
  Rng rng(11);
  for (int i = 0; i < 200; ++i) {
    auto r = ks.propose(KernelKind::Remove, w, rng);
    if (r) CHECK((r->move.units[0].id != 1 && r->move.units[0].id != 2));
  }
  // The candidate off every shared wall never becomes a door.
  for (int i = 0; i < 300; ++i) {
    auto a = ks.propose(KernelKind::Allocate, w, rng);
    if (a) CHECK(std::abs(a->move.doors[0].after->a.y - 5.0) > 1e-9);
  }
}

TEST_CASE("INTERCHANGE swap and shift are their own reverse", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  // L-shape: A tall on the left, B short on the right, tops aligned.
  const World w = world_of({fx.unit(1, {10, 10, 50, 40}), fx.unit(2, {50, 10, 90, 25})});
  check_round_trip(ks, KernelKind::Interchange, w, [](const Proposal& p) { return p.move.detail.variant == 1; });
  const auto p = find(ks, KernelKind::Interchange, w, [](const Proposal& q) { return q.move.detail.variant == 1; });
  REQUIRE(p);
  // After the swap: unit 1 is the lower part of the old A, unit 2 the full-width band.
  const World next = w.applied(p->move);
  CHECK(same_rect(next.find_unit(1)->rect, room_rect({10, 25, 50, 40})));
  CHECK(same_rect(next.find_unit(2)->rect, room_rect({10, 10, 90, 25})));
  check_inverse_scored(ks, KernelKind::Interchange, w, [](const Proposal& q) { return q.move.detail.variant == 0; });
  // Units that share no wall are never restructured.
  const World apart = world_of({fx.unit(1, {10, 10, 40, 40}), fx.unit(2, {60, 10, 90, 40})});
  Rng rng(2);
  for (int i = 0; i < 100; ++i) CHECK_FALSE(ks.propose(KernelKind::Interchange, apart, rng));
}

TEST_CASE("dominant orientation biases ADD without forbidding other orientations", "[indoor][kernels]") {
  KernelFixture fx;
  KernelParams p = params();
  KernelSet plain(fx.evidence, fx.sources(), p);
  p.orientation.enabled = true;
  p.orientation.dominant = 0.0;
  KernelSet biased(fx.evidence, fx.sources(), p);
  const World w;
  Move add_rotated;
  add_rotated.kind = KernelKind::Add;
  const Unit rot = fx.evidence.make_unit(1, OrientedRect{60, 30, 30, 20, 0.3});
  add_rotated.units.push_back({1, std::nullopt, rot});
  const double lp = plain.log_q(KernelKind::Add, w, add_rotated);
  const double lb = biased.log_q(KernelKind::Add, w, add_rotated);
  CHECK(std::isfinite(lb));
  CHECK(lb < lp);
  // The bias is periodic in 90 degrees and keeps at least `floor`.
  CHECK(p.orientation.factor(0.5 * kPi) == Approx(1.0));
  CHECK(p.orientation.factor(-kPi) == Approx(1.0));
  CHECK(p.orientation.factor(0.25 * kPi) >= p.orientation.floor);
  CHECK(p.orientation.factor(0.25 * kPi) < 0.5);
  Move add_room = add_rotated;
  add_room.units[0].after = fx.unit(1, fx.rooms[0]);
  CHECK(biased.log_q(KernelKind::Add, w, add_room) > plain.log_q(KernelKind::Add, w, add_room));
}

TEST_CASE("kernels decline on worlds they cannot change", "[indoor][kernels]") {
  KernelFixture fx;
  KernelSet ks(fx.evidence, fx.sources(), params());
  const World empty;
  Rng rng(1);
  for (KernelKind k : {KernelKind::Remove, KernelKind::Split, KernelKind::Merge, KernelKind::Shrink,
                       KernelKind::Dilate, KernelKind::Allocate, KernelKind::Delete, KernelKind::Interchange})
    CHECK_FALSE(ks.propose(k, empty, rng));
  CHECK(ks.propose(KernelKind::Add, empty, rng));
  KernelSet none(fx.evidence, KernelSources{}, params());
  CHECK_FALSE(none.propose(KernelKind::Add, empty, rng));
}

TEST_CASE("ALLOCATE does not stack a second door on a doorway the two units already have", "[indoor][kernels]") {
  KernelFixture fx;
  // The A-B doorway (x = 50, rows 22-28) detected again 0.3 cells across and 0.4 along, and a
  // second doorway on the same wall (rows 32-36) that does not overlap it.
  fx.door_cands.push_back({{50.3, 22.4}, {50.3, 28.4}, 0.9});
  fx.door_cands.push_back({{50, 32}, {50, 36}, 0.9});
  KernelSet ks(fx.evidence, fx.sources(), params());
  World w = world_of({fx.unit(1, fx.rooms[0]), fx.unit(2, fx.rooms[1]), fx.unit(3, fx.rooms[2]),
                      fx.unit(4, fx.rooms[3])});
  const auto at = [](double x, double y) {
    return [x, y](const Proposal& q) {
      return std::abs(q.move.doors[0].after->a.x - x) < 1e-9 && std::abs(q.move.doors[0].after->a.y - y) < 1e-9;
    };
  };
  // Before any door both A-B candidates are proposed.
  REQUIRE(find(ks, KernelKind::Allocate, w, at(50.3, 22.4)));
  const auto first = find(ks, KernelKind::Allocate, w, at(50.0, 22.0));
  REQUIRE(first);
  w.apply(first->move);
  Rng rng(5);
  int second = 0;
  for (int i = 0; i < 400; ++i) {
    const auto p = ks.propose(KernelKind::Allocate, w, rng);
    if (!p) continue;
    const Door& d = *p->move.doors[0].after;
    CHECK(!(std::abs(d.a.x - 50.3) < 1e-9 && std::abs(d.a.y - 22.4) < 1e-9));  // the copy, never
    if (std::abs(d.a.y - 32.0) < 1e-9) ++second;
  }
  CHECK(second > 0);  // another doorway of the same two units still is
  // The copy's density is 0 in this world, in the forward and the reverse evaluation alike.
  Move copy;
  copy.kind = KernelKind::Allocate;
  copy.doors.push_back({99, std::nullopt, fx.evidence.make_door(99, 1, 2, {50.3, 22.4}, {50.3, 28.4})});
  CHECK(ks.log_q(KernelKind::Allocate, w, copy) == -std::numeric_limits<double>::infinity());
  check_round_trip(ks, KernelKind::Allocate, w);
  check_round_trip(ks, KernelKind::Delete, w);
}
