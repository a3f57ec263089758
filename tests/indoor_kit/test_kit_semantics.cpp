// The semantic half: the extractor blocks (Table 3.6 classifier, adjacency / connecting walls,
// door count, wall-length difference) and the semantic layer over the shared evaluator: unit
// types from the program's type group, conditional prior bindings, the evidence cache.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "stdlib/indoor/blocks/walls.h"
#include "stdlib/indoor/free_distance.h"
#include "stdlib/indoor/io/specks.h"
#include "stdlib/indoor/kit/semantic_layer.h"
#include "stdlib/indoor/map_evidence.h"
#include "tests/indoor_kit/binding.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::kit;
using namespace ksmc::tests::indoor_kit;

namespace {

World world_of(const std::vector<OrientedRect>& rects, const std::vector<std::pair<UnitId, UnitId>>& doors = {}) {
  Move m;
  UnitId id = 1;
  for (const auto& r : rects) m.units.push_back({id, std::nullopt, Unit{id++, r}});
  DoorId did = 1;
  for (auto [a, b] : doors) {
    Door d;
    d.id = did++;
    d.unit_a = a;
    d.unit_b = b;
    m.doors.push_back({d.id, std::nullopt, d});
  }
  World w;
  w.apply(m);
  return w;
}

}  // namespace

TEST_CASE("Table 3.6 blocks: size and aspect ratio give exactly one of room, corridor or hall", "[indoor_kit]") {
  // 4 x 3 m, 9.5 x 2 m, 14 x 8 m, 20 x 2 m, ratio exactly 3, 20 x 4.5 m, 30 x 3.9 m.
  const World w = world_of({{0, 0, 80, 60, 0}, {0, 0, 190, 40, 0}, {0, 0, 280, 160, 0}, {0, 0, 400, 40, 0},
                            {0, 0, 60, 20, 0.3}, {0, 0, 400, 90, 0}, {0, 0, 600, 78, 0}});
  const blk::Scene s(w, 0.05);
  // Table 3.6 as printed (corridor_width 0): big size wins over the ratio.
  const int printed[] = {0, 1, 2, 2, 0, 2, 2};
  // corridor_width 4 m: a unit of big ratio at most 4 m wide is a corridor at any length; the
  // 4.5 m wide one stays a hall.
  const int narrow[] = {0, 1, 2, 1, 0, 2, 1};
  for (const double width : {0.0, 4.0}) {
    const int* want = width > 0.0 ? narrow : printed;
    for (std::int32_t i = 0; i < 7; ++i) {
      const bool r = blk::geom::room_like(s, s.rect(i), 10.0, 3.0, width);
      const bool c = blk::geom::corridor_like(s, s.rect(i), 10.0, 3.0, width);
      const bool h = blk::geom::hall_like(s, s.rect(i), 10.0, 3.0, width);
      INFO("unit " << i << ", corridor_width " << width);
      CHECK(r + c + h == 1);
      CHECK((want[i] == 0 ? r : want[i] == 1 ? c : h));
    }
  }
  CHECK(blk::geom::hall_like(s, s.rect(0), 3.5, 3.0, 4.0));  // 4 m > 3.5 m, ratio 1.33: not elongated
}

TEST_CASE("connecting walls, adjacency and the wall-length difference", "[indoor_kit]") {
  const OrientedRect a{50, 50, 100, 60, 0};   // x 0..100, y 20..80
  const OrientedRect b{130, 50, 60, 60, 0};   // x 100..160: shares a's right wall
  const OrientedRect c{300, 50, 60, 60, 0};   // far away
  const OrientedRect d{50, 110, 100, 60, 0};  // y 80..140: shares a's bottom wall, same length
  const OrientedRect e{133, 50, 60, 40, 0};   // 3 cells from a, shorter
  auto ab = blk::connecting_walls(a, b, 2.0);
  REQUIRE(ab);
  CHECK(ab->length_a == Approx(60));
  CHECK(ab->length_b == Approx(60));
  CHECK(!blk::connecting_walls(a, c, 2.0));
  CHECK(!blk::connecting_walls(a, e, 0.5));  // 3 cells apart: beyond 2 * 0.5 + 1

  const World w = world_of({a, b, c, d, e});
  const blk::Scene s(w, 0.05);
  CHECK(blk::geom::adjacent(s, s.rect(0), s.rect(1), 2.0));
  CHECK(blk::geom::adjacent(s, s.rect(1), s.rect(0), 2.0));
  CHECK(!blk::geom::adjacent(s, s.rect(0), s.rect(2), 2.0));
  CHECK(!blk::geom::adjacent(s, s.rect(0), s.rect(0), 2.0));  // never adjacent to itself
  CHECK(!blk::geom::adjacent(s, s.rect(0), s.rect(4), 0.5));
  CHECK(blk::wall_length_diff(s, s.rect(0), s.rect(3)) == Approx(0.0).margin(1e-9));
  CHECK(blk::wall_length_diff(s, s.rect(0), s.rect(4)) == Approx(1.0));  // 60 vs 40 cells = 1 m
  CHECK(blk::wall_length_diff(s, s.rect(4), s.rect(0)) == Approx(1.0));
  CHECK(blk::wall_length_diff(s, s.rect(0), s.rect(2)) == 0.0);  // no connecting walls
  CHECK(blk::gaussian(s, 0.6, 0.3) == Approx(-2.0));
}

TEST_CASE("cut_across_corridor: a short cut between units that make a long rectangle", "[indoor_kit]") {
  const OrientedRect left{50, 20, 100, 40, 0};    // x 0..100, y 0..40: a corridor piece 40 cells wide
  const OrientedRect right{150, 20, 100, 40, 0};  // x 100..200: the next piece, cut 40 cells long
  CHECK(blk::cut_across_corridor(left, right, 60, 3.0));   // 200 long across a 40-cell cut
  CHECK(blk::cut_across_corridor(right, left, 60, 3.0));   // symmetric
  CHECK(!blk::cut_across_corridor(left, right, 30, 3.0));  // the cut is longer than max_cut
  CHECK(!blk::cut_across_corridor(left, right, 60, 6.0));  // 200 < 6 x 40
  // Above, the shared walls are |h| sides (edges 1 and 3). Pieces stacked along y share |w|
  // sides (edges 0 and 2), and so do pieces along x turned by a quarter.
  const OrientedRect up{20, 50, 40, 100, 0}, down{20, 150, 40, 100, 0};
  CHECK(blk::cut_across_corridor(up, down, 60, 3.0));
  CHECK(blk::cut_across_corridor(OrientedRect{50, 20, 40, 100, 1.5707963267948966},
                                 OrientedRect{150, 20, 40, 100, 1.5707963267948966}, 60, 3.0));
  // A room cut lengthwise: a cut 100 cells long, 80 across.
  const OrientedRect a{50, 20, 100, 40, 0}, b{50, 60, 100, 40, 0};
  CHECK(!blk::cut_across_corridor(a, b, 150, 3.0));
  CHECK(blk::cut_across_corridor(a, b, 150, 0.8));
  CHECK(!blk::cut_across_corridor(left, OrientedRect{500, 20, 100, 40, 0}, 60, 3.0));  // no shared wall
}

TEST_CASE("open_join: a free run on the midline between two joined units longer than max_gap", "[indoor_kit]") {
  // Two pieces of a corridor 2 m wide at 0.05 m per cell: x 0..100 and 100..200, y 0..40,
  // a wall 2 cells thick at x 99..100 with a gap of `gap` cells from y = 4.
  const auto map_with_gap = [](int gap) {
    ClassGrid map(40, 200, static_cast<std::uint8_t>(Cell::Free));
    map(cv::Rect(99, 0, 2, 40)).setTo(static_cast<std::uint8_t>(Cell::Occupied));
    if (gap > 0) map(cv::Rect(99, 4, 2, gap)).setTo(static_cast<std::uint8_t>(Cell::Free));
    return map;
  };
  const World w = world_of({{50, 20, 100, 40, 0}, {150, 20, 100, 40, 0}});
  const ClassGrid door = map_with_gap(18), cut = map_with_gap(34), wall = map_with_gap(0);
  const blk::Scene sd(w, 0.05, &door), sc(w, 0.05, &cut), sw(w, 0.05, &wall);
  CHECK(blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 1.5, 1.0, 1.2));   // a 1.7 m run > 1.5 m
  CHECK(blk::geom::open_join(sc, sc.rect(1), sc.rect(0), 2.0, 1.5, 1.0, 1.2));   // symmetric
  CHECK(!blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 2.0, 1.0, 1.2));  // not > 2 m
  CHECK(!blk::geom::open_join(sd, sd.rect(0), sd.rect(1), 2.0, 1.5, 1.0, 1.2));  // a 0.9 m door
  CHECK(blk::geom::open_join(sd, sd.rect(0), sd.rect(1), 2.0, 0.8, 1.0, 1.2));
  CHECK(!blk::geom::open_join(sw, sw.rect(0), sw.rect(1), 2.0, 0.1, 1.0, 1.2));  // a wall: no run at all
  CHECK(!blk::geom::open_join(sc, sc.rect(0), sc.rect(0), 2.0, 0.1, 1.0, 1.2));  // never with itself
  const blk::Scene none(w, 0.05);
  CHECK(!blk::geom::open_join(none, none.rect(0), none.rect(1), 2.0, 0.1, 1.0, 1.2));  // false without a map
  // Units that do not join (a gap of 20 cells between them) are never open.
  const World apart = world_of({{50, 20, 100, 40, 0}, {170, 20, 100, 40, 0}});
  const blk::Scene sa(apart, 0.05, &cut);
  CHECK(!blk::geom::open_join(sa, sa.rect(0), sa.rect(1), 2.0, 0.1, 1.0, 1.2));
  // The share test: the 1.7 m run is 34 of the 40 cells the two walls share.
  CHECK(blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 2.0, 0.75, 1.2));   // 0.85 > 0.75, 1.7 m >= 1.2 m
  CHECK(blk::geom::open_join(sc, sc.rect(1), sc.rect(0), 2.0, 2.0, 0.75, 1.2));   // symmetric
  CHECK(!blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 2.0, 0.9, 1.2));   // 0.85 < 0.9
  CHECK(!blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 2.0, 0.75, 1.8));  // 1.7 m < min_run
  CHECK(!blk::geom::open_join(sd, sd.rect(0), sd.rect(1), 2.0, 2.0, 0.75, 0.1));  // a door: 0.45 of the join
  CHECK(!blk::geom::open_join(sw, sw.rect(0), sw.rect(1), 2.0, 2.0, 0.01, 0.0));  // a wall: no run at all
}

TEST_CASE("open_join: a speck on the join of two corridor pieces is no wall once cleared", "[indoor_kit]") {
  // Two pieces of a corridor 2 m wide (x 0..100 and 100..200, y 0..40), no wall between them,
  // and one occupied cell on the line between them, at y = 15 or 25 (a SLAM map's speck).
  const World w = world_of({{50, 20, 100, 40, 0}, {150, 20, 100, 40, 0}});
  const int y = GENERATE(15, 25);
  ClassGrid map(40, 200, static_cast<std::uint8_t>(Cell::Free));
  map(y, 100) = static_cast<std::uint8_t>(Cell::Occupied);
  const blk::Scene raw(w, 0.05, &map);
  // The longest free run is 25 cells (1.25 m), under 3/4 of the 40 and under 2 m: not open.
  CHECK(!blk::geom::open_join(raw, raw.rect(0), raw.rect(1), 2.0, 2.0, 0.75, 1.2));
  ClassGrid cleared = map.clone();
  CHECK(io::clear_specks(cleared, 2) == 1);
  const blk::Scene sc(w, 0.05, &cleared);
  CHECK(blk::geom::open_join(sc, sc.rect(0), sc.rect(1), 2.0, 2.0, 0.75, 1.2));
}

TEST_CASE("end_join: b lies off a's shorter side", "[indoor_kit]") {
  // a: a corridor piece x 0..40, y 0..100 (its |w| sides, edges 0 and 2, are the short ones);
  // b: the next piece, y 100..200; c: a room x 40..240 beside a's long side; d: far away.
  const World w = world_of({{20, 50, 40, 100, 0}, {20, 150, 40, 100, 0}, {140, 50, 200, 100, 0}, {500, 500, 40, 40, 0}});
  const blk::Scene s(w, 0.05);
  CHECK(blk::geom::end_join(s, s.rect(0), s.rect(1), 2.0));   // b off a's end
  CHECK(blk::geom::end_join(s, s.rect(1), s.rect(0), 2.0));   // and a off b's
  CHECK(!blk::geom::end_join(s, s.rect(0), s.rect(2), 2.0));  // c beside a's long side
  CHECK(blk::geom::end_join(s, s.rect(2), s.rect(0), 2.0));   // a off c's end (c's 100-cell side)
  CHECK(!blk::geom::end_join(s, s.rect(0), s.rect(3), 2.0));  // no connecting walls
  CHECK(!blk::geom::end_join(s, s.rect(0), s.rect(0), 2.0));  // never with itself
  // A quarter turn swaps the roles of the sides.
  const World t = world_of({{50, 20, 40, 100, 1.5707963267948966}, {150, 20, 40, 100, 1.5707963267948966}});
  const blk::Scene st(t, 0.05);
  CHECK(blk::geom::end_join(st, st.rect(0), st.rect(1), 2.0));
}

TEST_CASE("multi_door counts the doors attached to a unit", "[indoor_kit]") {
  const World w = world_of({{40, 30, 80, 60, 0}, {120, 30, 80, 60, 0}, {80, 80, 160, 40, 0}}, {{1, 3}, {2, 3}, {1, 2}});
  const blk::Scene s(w, 0.05);
  CHECK(blk::geom::multi_door(s, s.rect(2), s.segments(), 2));
  CHECK(!blk::geom::multi_door(s, s.rect(2), s.segments(), 3));
  CHECK(!blk::geom::multi_door(s, s.rect(0), s.segments().subspan(0, 1), 2));
}

TEST_CASE("hollow: a unit over a region the sensor never saw into, wider than min_width", "[indoor_kit]") {
  // 12 x 10 m of free space at 0.05 m per cell round an unknown block 6 m square (x 60..180,
  // y 40..160), and a 1 m square of unknown speckle in a corner. Points are sampled every
  // min_width / 4, so a region is always found when it holds a disc of 1.35 x min_width, and
  // never when it holds none of min_width.
  ClassGrid map(200, 240, static_cast<std::uint8_t>(Cell::Free));
  map(cv::Rect(60, 40, 120, 120)).setTo(static_cast<std::uint8_t>(Cell::Unknown));
  map(cv::Rect(5, 5, 20, 20)).setTo(static_cast<std::uint8_t>(Cell::Unknown));
  const cv::Mat1f field = free_distance(map);
  CHECK(field(100, 120) == Approx(60.0f));  // the block's centre, 3 m from free space
  CHECK(field(0, 0) == 0.0f);
  // The whole map; the block alone; a strip above it; the whole map turned by 0.3 rad.
  const World w = world_of({{120, 100, 240, 200, 0}, {120, 100, 120, 120, 0}, {120, 18, 240, 36, 0}, {120, 100, 170, 170, 0.3}});
  const blk::Scene s(w, 0.05, &map, &field);
  CHECK(blk::geom::hollow(s, s.rect(0), 4.0));   // a 6 m block holds a 4 m disc
  CHECK(!blk::geom::hollow(s, s.rect(0), 6.5));  // but no 6.5 m one
  CHECK(blk::geom::hollow(s, s.rect(1), 4.0));
  CHECK(blk::geom::hollow(s, s.rect(3), 4.0));
  CHECK(!blk::geom::hollow(s, s.rect(2), 4.0));  // free space and the speckle
  CHECK(!blk::geom::hollow(s, s.rect(2), 1.2));  // the speckle holds no 1.2 m disc
  CHECK(blk::geom::hollow(s, s.rect(2), 0.6));   // but a 0.6 m one
  // Past the map's edge counts as unseen: a unit reaching 3 m beyond it.
  const World out = world_of({{260, 100, 120, 100, 0}});
  CHECK(blk::geom::hollow(blk::Scene(out, 0.05, &map, &field), out.units()[0], 4.0));
  // Far outside, and at a point that is no point: no overflow, unseen.
  CHECK(free_distance_at(field, 1e12, -1e12) > 1e11);
  CHECK(std::isinf(free_distance_at(field, std::nan(""), 3.0)));
  // Without the field (a kit with no map) nothing is hollow.
  CHECK(!blk::geom::hollow(blk::Scene(w, 0.05, &map), s.rect(0), 4.0));
  // A map with no free cell: every cell is far from free space.
  const ClassGrid blind(50, 50, static_cast<std::uint8_t>(Cell::Unknown));
  CHECK(free_distance(blind)(25, 25) > 50.0f);
}

TEST_CASE("the semantic layer types the units from the type group and is cached by evidence", "[indoor_kit]") {
  const blk::Binding b = indoor_binding();
  const KitPlan plan = make_plan(b);
  SemanticLayer sem(b, plan, 0.05, nullptr, 1);
  CHECK(sem.type_names() == std::vector<std::string>{"Room", "Corr", "Hall", "Other"});
  // Two rooms (4 m x 3 m) side by side above a corridor (9 m x 2 m), and a hall (12 m x 8 m).
  const World w = world_of({{40, 30, 80, 60, 0}, {120, 30, 80, 60, 0}, {80, 80, 160, 40, 0}, {300, 100, 240, 160, 0}});
  const SemanticResult r = sem.evaluate(w);
  REQUIRE(r.ids == std::vector<UnitId>{1, 2, 3, 4});
  CHECK(r.type == std::vector<int>{0, 0, 1, 2});  // Room, Room, Corr, Hall
  for (std::size_t i = 0; i < 4; ++i) {
    double t = 0;
    for (double p : r.type_probs[i]) t += p;
    CHECK(t == Approx(1.0).epsilon(0.05));
  }
  // The SaLe prior holds for the two adjacent rooms (in both orders), never for units that
  // are not adjacent.
  const auto has = [&](UnitId x, UnitId y) {
    return std::find(r.terms.begin(), r.terms.end(), PriorBinding{0, {x, y}}) != r.terms.end();
  };
  CHECK(has(1, 2));
  CHECK(has(2, 1));
  for (const auto& t : r.terms) {
    CHECK(t.units[0] != 4);
    CHECK(t.units[1] != 4);
  }
  // The terms are part of the world's knowledge score: same-length rooms add nothing, a
  // shorter one is penalised in both orders, equally.
  CHECK(r.log_terms == Approx(0.0).margin(1e-12));
  const World shorter = world_of({{40, 30, 80, 60, 0}, {120, 30, 80, 48, 0}});  // 60 vs 48 cells: 0.6 m
  const SemanticResult rs = sem.evaluate(shorter);
  REQUIRE(rs.terms.size() == 2);
  CHECK(rs.log_terms < 0.0);
  CHECK(rs.log_knowledge() == Approx(rs.log_terms + rs.log_mln));
  // The outputs: every query atom by name, units u<id>.
  const auto q = sem.queries_json(r);
  CHECK(q.at("Room").at("u1").get<double>() == Approx(r.type_probs[0][0]));
  CHECK(q.contains("SaLe"));
  CHECK(sem.evidence_db(r).find("\nAdj(u1,u2)\n") != std::string::npos);
  CHECK(sem.evidence_db(r).find("\n!Adj(u1,u4)\n") != std::string::npos);
  // Same evidence: no new inference.
  const auto inferences = sem.stats().inferences;
  const SemanticResult r2 = sem.evaluate(w);
  CHECK(sem.stats().inferences == inferences);
  CHECK(r2.type_probs == r.type_probs);
}

namespace {
double minus_one(const blk::Scene&, const std::int32_t*) { return -1.0; }
}  // namespace

TEST_CASE("conditional priors on any predicate and condition", "[indoor_kit]") {
  blk::Binding b = indoor_binding();
  // prior for u where !RoLi(u): a constant term; prior for a, b where Adj(a, b): another.
  b.conditional_priors = {{{gen::kType_unit}, {{false, gen::kPred_RoLi, {0}, dom::Cmp::gt, 0.0, true}}, &minus_one, "not room-like"},
                          {{gen::kType_unit, gen::kType_unit}, {{false, gen::kPred_Adj, {0, 1}, dom::Cmp::gt, 0.0, false}}, &minus_one, "adjacent"}};
  const KitPlan plan = make_plan(b);
  SemanticLayer sem(b, plan, 0.05, nullptr, 1);
  const World w = world_of({{40, 30, 80, 60, 0}, {120, 30, 80, 60, 0}, {80, 80, 160, 40, 0}, {300, 100, 240, 160, 0}});
  const SemanticResult r = sem.evaluate(w);
  std::size_t not_room = 0, adjacent = 0;
  for (const auto& t : r.terms) (t.prior == 0 ? not_room : adjacent) += 1;
  CHECK(not_room == 2);   // the corridor and the hall
  CHECK(adjacent == 6);   // 1-2, 1-3, 2-3 in both orders
  CHECK(r.log_terms == Approx(-8.0));
}
