// Incremental likelihood (eq. 3.6) and weak prior (eq. 3.3-3.5) against full recomputation over
// 10^5 random moves: add, remove, wall shift, scale, split, merge, type change, door add/remove,
// with about a third of the moves reverted as an MH rejection would.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/scored_world.h"
#include "tests/indoor/synthetic_map.h"

using namespace ksmc::stdlib::indoor;
using ksmc::tests::indoor::draw_plan;
using ksmc::tests::indoor::Room;

namespace {

ScoreParams test_params() {
  ScoreParams p;
  p.raster.wall_thickness = 1.5;
  LikelihoodTable lenient = LikelihoodTable::table_3_1();
  lenient.p[0][1] = 0.4;  // predicted free, observed unknown: lenient for rooms/halls
  lenient.p[0][2] = 0.3;
  p.tables = {LikelihoodTable::table_3_1(), lenient};
  p.prior.adjacency_distance = 3.0;
  return p;
}

bool close_rel(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::max({1.0, std::abs(a), std::abs(b)});
}

class RandomMoves {
 public:
  RandomMoves(int rows, int cols, std::uint64_t seed) : rows_(rows), cols_(cols), rng_(seed) {}

  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

  OrientedRect random_rect() {
    const double th = pick(3) == 0 ? uni(-1.5, 1.5) : (pick(2) ? 0.0 : 0.5 * kPi);
    // Partly outside the map now and then.
    return OrientedRect{uni(-10, cols_ + 10), uni(-10, rows_ + 10), uni(2, 40), uni(2, 40), th};
  }

  Unit make(UnitId id, const OrientedRect& r) {
    Unit u;
    u.id = id;
    u.rect = r;
    u.lut_class = static_cast<std::uint8_t>(pick(2));
    return u;
  }

  // A random move that fits `w`, or nullopt when the drawn kind cannot apply.
  std::optional<Move> next(const World& w) {
    const auto units = w.units();
    const int kind = pick(9);
    Move m;
    auto free_unit = [&]() -> const Unit* {
      if (units.empty()) return nullptr;
      const Unit& u = units[static_cast<std::size_t>(pick(static_cast<int>(units.size())))];
      return w.door_count(u.id) == 0 ? &u : nullptr;
    };
    if (kind == 0 || units.size() < 3) {  // add
      m.units.push_back({w.next_unit_id(), std::nullopt, make(w.next_unit_id(), random_rect())});
      return m;
    }
    if (kind == 1) {  // remove, with its doors
      const Unit& u = units[static_cast<std::size_t>(pick(static_cast<int>(units.size())))];
      for (const Door& d : w.doors())
        if (d.unit_a == u.id || d.unit_b == u.id) m.doors.push_back({d.id, d, std::nullopt});
      m.units.push_back({u.id, u, std::nullopt});
      return m;
    }
    if (kind == 2 || kind == 3) {  // wall shift / scale
      const Unit* u = free_unit();
      if (!u) return std::nullopt;
      Unit a = *u;
      if (kind == 2) {
        const Box b = shift_box_wall(own_box(u->rect), pick(4), uni(-4, 4));
        if (b.width() < 1 || b.height() < 1) return std::nullopt;
        a.rect = rect_from_box(b, Frame(u->rect.theta));
      } else {
        a.rect.w *= uni(0.7, 1.4);
        a.rect.h *= uni(0.7, 1.4);
      }
      m.units.push_back({u->id, *u, a});
      return m;
    }
    if (kind == 4) {  // split
      const Unit* u = free_unit();
      if (!u) return std::nullopt;
      const Box b = own_box(u->rect);
      const double cut = uni(b.x0 + 0.5, b.x1 - 0.5);
      const Frame f(u->rect.theta);
      m.units.push_back({u->id, *u, std::nullopt});
      const UnitId id = w.next_unit_id();
      m.units.push_back({id, std::nullopt, make(id, rect_from_box({b.x0, cut, b.y0, b.y1}, f))});
      m.units.push_back({id + 1, std::nullopt, make(id + 1, rect_from_box({cut, b.x1, b.y0, b.y1}, f))});
      return m;
    }
    if (kind == 5) {  // merge (bounding box in the first unit's frame)
      const Unit* a = free_unit();
      const Unit* b = free_unit();
      if (!a || !b || a->id == b->id) return std::nullopt;
      const Frame f(a->rect.theta);
      Box box{1e300, -1e300, 1e300, -1e300};
      for (const Unit* u : {a, b})
        for (const Point2& c : u->rect.corners()) {
          const Point2 l = f.to_local(c);
          box = {std::min(box.x0, l.x), std::max(box.x1, l.x), std::min(box.y0, l.y), std::max(box.y1, l.y)};
        }
      m.units.push_back({a->id, *a, std::nullopt});
      m.units.push_back({b->id, *b, std::nullopt});
      m.units.push_back({w.next_unit_id(), std::nullopt, make(w.next_unit_id(), rect_from_box(box, f))});
      return m;
    }
    if (kind == 6) {  // type change
      const Unit& u = units[static_cast<std::size_t>(pick(static_cast<int>(units.size())))];
      Unit a = u;
      a.lut_class = static_cast<std::uint8_t>(1 - u.lut_class);
      m.units.push_back({u.id, u, a});
      return m;
    }
    if (kind == 7) {  // door add between two units, on a wall of the first
      const Unit& a = units[static_cast<std::size_t>(pick(static_cast<int>(units.size())))];
      const Unit& b = units[static_cast<std::size_t>(pick(static_cast<int>(units.size())))];
      if (a.id == b.id) return std::nullopt;
      const auto c = a.rect.corners();
      const int j = pick(4);
      const Point2 p = c[static_cast<std::size_t>(j)], q = c[static_cast<std::size_t>((j + 1) % 4)];
      const double t0 = uni(0, 0.8), t1 = t0 + uni(0.05, 0.2);
      Door d;
      d.id = w.next_door_id();
      d.unit_a = std::min(a.id, b.id);
      d.unit_b = std::max(a.id, b.id);
      d.a = {p.x + t0 * (q.x - p.x), p.y + t0 * (q.y - p.y)};
      d.b = {p.x + t1 * (q.x - p.x), p.y + t1 * (q.y - p.y)};
      m.doors.push_back({d.id, std::nullopt, d});
      return m;
    }
    // door remove
    if (w.doors().empty()) return std::nullopt;
    const Door& d = w.doors()[static_cast<std::size_t>(pick(static_cast<int>(w.doors().size())))];
    m.doors.push_back({d.id, d, std::nullopt});
    return m;
  }

 private:
  int rows_, cols_;
  std::mt19937_64 rng_;
};

}  // namespace

TEST_CASE("incremental likelihood and weak prior match full recomputation over 1e5 random moves",
          "[indoor][score]") {
  const int rows = 90, cols = 120;
  const ClassGrid map = draw_plan(rows, cols, {{5, 5, 50, 40}, {50, 5, 110, 40}, {5, 40, 110, 55}, {20, 55, 70, 85}},
                                  2, {{50, 20}, {30, 40}});
  ScoredWorld sw(map, test_params());
  RandomMoves gen(rows, cols, 42);

  const double empty_ll = sw.log_likelihood();
  REQUIRE(close_rel(empty_ll, sw.recompute_log_likelihood(), 1e-12));

  int applied = 0, reverted = 0, checks = 0, max_units = 0;
  std::int64_t max_overlap = 0, max_theta = 0;
  for (int i = 0; i < 100000; ++i) {
    auto m = gen.next(sw.world());
    if (!m) continue;  // the drawn kind did not fit this world
    const double ll0 = sw.log_likelihood(), lp0 = sw.log_prior();
    sw.apply(*m);
    ++applied;
    if (gen.pick(3) == 0) {
      sw.revert(*m);
      ++reverted;
      // A rejection restores the totals bit for bit.
      REQUIRE(sw.log_likelihood() == ll0);
      REQUIRE(sw.log_prior() == lp0);
    }
    max_units = std::max(max_units, static_cast<int>(sw.world().units().size()));
    max_overlap = std::max(max_overlap, sw.overlap_cells());
    max_theta = std::max(max_theta, sw.misaligned_pairs());
    // Keep the world from growing without bound.
    if (sw.world().units().size() > 25) {
      const Unit u = sw.world().units()[0];
      Move rm;
      for (const Door& d : sw.world().doors())
        if (d.unit_a == u.id || d.unit_b == u.id) rm.doors.push_back({d.id, d, std::nullopt});
      rm.units.push_back({u.id, u, std::nullopt});
      sw.apply(rm);
    }
    if (i % 20 == 0) {
      ++checks;
      const double full_ll = sw.recompute_log_likelihood();
      const double full_lp = sw.recompute_log_prior();
      if (!close_rel(sw.log_likelihood(), full_ll, 1e-9) || !close_rel(sw.log_prior(), full_lp, 1e-9)) {
        INFO("move " << i << ": incremental ll " << sw.log_likelihood() << " full " << full_ll
                     << ", incremental lp " << sw.log_prior() << " full " << full_lp);
        REQUIRE(false);
      }
    }
  }
  INFO("applied " << applied << " reverted " << reverted << " checks " << checks);
  CHECK(applied > 80000);
  CHECK(checks >= 4000);
  // Final state, whatever the last draw was.
  REQUIRE(close_rel(sw.log_likelihood(), sw.recompute_log_likelihood(), 1e-9));
  REQUIRE(close_rel(sw.log_prior(), sw.recompute_log_prior(), 1e-9));
  // The random walk exercised overlaps, misaligned neighbours and several units.
  CHECK(max_units >= 10);
  CHECK(max_overlap > 0);
  CHECK(max_theta > 0);
  CHECK(sw.log_likelihood() != empty_ll);
  // The grid's predicted class (read from the cached histogram index) equals the
  // classification of the cell's counts.
  int mismatched = 0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      mismatched += sw.coverage().predicted(r, c) != predicted_class(sw.coverage().counts(r, c));
  CHECK(mismatched == 0);
}

TEST_CASE("abutting units share no cell and a full rescore equals the incremental state",
          "[indoor][score]") {
  const ClassGrid map = draw_plan(40, 60, {{5, 5, 30, 30}, {30, 5, 55, 30}}, 2);
  ScoredWorld sw(map, test_params());
  Move m;
  Unit a, b;
  a.id = 1;
  a.rect = ksmc::tests::indoor::room_rect({5, 5, 30, 30});
  b.id = 2;
  b.rect = ksmc::tests::indoor::room_rect({30, 5, 55, 30});
  m.units = {{1, std::nullopt, a}, {2, std::nullopt, b}};
  sw.apply(m);
  CHECK(sw.overlap_cells() == 0);
  CHECK(sw.misaligned_pairs() == 0);
  CHECK(sw.coverage().counts(10, 29).area[0] == 1);
  CHECK(sw.coverage().counts(10, 30).area[0] == 1);
  CHECK(sw.coverage().predicted(10, 30) == Predicted::Wall);
  CHECK(sw.coverage().predicted(15, 17) == Predicted::Free);
  CHECK(sw.coverage().predicted(2, 2) == Predicted::Unknown);
  // Tilting b by 20 degrees makes its walls meet a's at a non-right angle and overlap a.
  Unit b2 = b;
  b2.rect.theta = 20.0 * kPi / 180.0;
  sw.apply(Move{KernelKind::Shrink, {{2, b, b2}}, {}, {}});
  CHECK(sw.misaligned_pairs() > 0);
  CHECK(sw.overlap_cells() > 0);
  CHECK(sw.log_prior() < 0.0);
  const double ll = sw.log_likelihood();
  ScoredWorld fresh(map, test_params());
  fresh.reset(sw.world());
  CHECK(fresh.log_likelihood() == ll);
  CHECK(fresh.misaligned_pairs() == sw.misaligned_pairs());
}

TEST_CASE("bad inputs are reported, not crashed on", "[indoor][score]") {
  ClassGrid bad(5, 5, std::uint8_t{0});
  bad(3, 4) = 7;
  CHECK_THROWS_WITH(ScoredWorld(bad, ScoreParams{}), Catch::Contains("row 3, col 4"));
  ScoreParams p;
  p.tables[0].p[1][1] = 0.0;
  CHECK_THROWS_WITH(ScoredWorld(ClassGrid(5, 5, std::uint8_t{0}), p), Catch::Contains("must be finite and > 0"));
  ScoredWorld sw(ClassGrid(5, 5, std::uint8_t{0}), ScoreParams{});
  Unit u;
  u.id = 3;
  Move rm{KernelKind::Remove, {{3, u, std::nullopt}}, {}, {}};
  const double ll = sw.log_likelihood();
  CHECK_THROWS_WITH(sw.apply(rm), Catch::Contains("missing"));
  CHECK(sw.log_likelihood() == ll);
  // A stale 'before' state is refused too (it would corrupt the coverage counts).
  u.rect = OrientedRect{2, 2, 2, 2, 0.0};
  sw.apply(Move{KernelKind::Add, {{3, std::nullopt, u}}, {}, {}});
  const double ll2 = sw.log_likelihood();
  Unit stale = u;
  stale.rect.w = 3;
  CHECK_THROWS_WITH(sw.apply(Move{KernelKind::Remove, {{3, stale, std::nullopt}}, {}, {}}),
                    Catch::Contains("differs from the move's 'before'"));
  CHECK(sw.log_likelihood() == ll2);
}

TEST_CASE("a preview scores a move like apply, commit equals apply and discard restores bit for bit",
          "[indoor][score]") {
  const int rows = 90, cols = 120;
  const ClassGrid map = draw_plan(rows, cols, {{5, 5, 50, 40}, {50, 5, 110, 40}, {5, 40, 110, 55}, {20, 55, 70, 85}},
                                  2, {{50, 20}, {30, 40}});
  ScoredWorld sw(map, test_params()), ref(map, test_params());
  RandomMoves gen(rows, cols, 7);
  int previewed = 0, committed = 0, discarded = 0, not_previewable = 0;
  for (int i = 0; i < 20000; ++i) {
    auto m = gen.next(sw.world());
    if (!m) continue;
    if (sw.world().units().size() > 25) continue;
    const double ll0 = sw.log_likelihood(), lp0 = sw.log_prior();
    if (!sw.preview(*m)) {
      ++not_previewable;
      CHECK_FALSE(sw.previewing());
      sw.apply(*m);
      ref.apply(*m);
      continue;
    }
    ++previewed;
    ref.apply(*m);
    // The preview reads exactly as the applied move.
    REQUIRE(sw.log_likelihood() == ref.log_likelihood());
    REQUIRE(sw.log_prior() == ref.log_prior());
    REQUIRE(sw.world().units().size() == ref.world().units().size());
    CHECK_THROWS_AS(sw.apply(*m), std::logic_error);
    if (gen.pick(2) == 0) {
      sw.discard();
      ref.revert(*m);
      ++discarded;
      REQUIRE(sw.log_likelihood() == ll0);
      REQUIRE(sw.log_prior() == lp0);
    } else {
      sw.commit();
      ++committed;
      REQUIRE(sw.log_likelihood() == ref.log_likelihood());
      REQUIRE(sw.log_prior() == ref.log_prior());
    }
    if (i % 200 == 0) REQUIRE(close_rel(sw.log_likelihood(), sw.recompute_log_likelihood(), 1e-9));
  }
  CHECK(previewed > 2000);
  CHECK(committed > 1000);
  CHECK(discarded > 1000);
  CHECK(not_previewable > 100);  // door moves and large moves take the apply path
  CHECK_THROWS_AS(sw.commit(), std::logic_error);
}

TEST_CASE("one_cell_gain: ln 8 for Table 3.1, the weakest table decides", "[indoor]") {
  CHECK(one_cell_gain(LikelihoodModel()) == Approx(std::log(8.0)));
  LikelihoodTable soft = LikelihoodTable::table_3_1();
  soft.p[0][2] = 0.4;  // predicted free, observed occupied: lenient
  CHECK(one_cell_gain(LikelihoodModel({LikelihoodTable::table_3_1(), soft})) == Approx(std::log(0.8 / 0.4)));
  LikelihoodTable flat = LikelihoodTable::table_3_1();
  flat.p[1][1] = 0.1;
  CHECK_THROWS_AS(one_cell_gain(LikelihoodModel({flat})), std::invalid_argument);
}
