// The kit's reading of a binding: kernels bound by their declared moves and sources (whatever
// their names), the weak prior and tables, the type group of the program, lenient types by id.
#include <catch2/catch.hpp>

#include <cmath>

#include "stdlib/indoor/kit/plan.h"
#include "tests/indoor_kit/binding.h"

using namespace ksmc::stdlib::indoor;
using namespace ksmc::stdlib::indoor::kit;
using namespace ksmc::tests::indoor_kit;

TEST_CASE("the binding of indoor.ksm gives the kit's plan", "[indoor_kit]") {
  const blk::Binding b = indoor_binding();
  const KitPlan p = make_plan(b);
  REQUIRE(p.kernels.size() == 9);
  CHECK(p.pools.size() == 5);  // ADD / REMOVE, SPLIT / MERGE, SHRINK / DILATE, ALLOCATE / DELETE, INTERCHANGE
  const KernelKind kinds[] = {KernelKind::Add,    KernelKind::Remove,   KernelKind::Split,
                              KernelKind::Merge,  KernelKind::Shrink,   KernelKind::Dilate,
                              KernelKind::Allocate, KernelKind::Delete, KernelKind::Interchange};
  for (std::size_t i = 0; i < 9; ++i) {
    CHECK(p.kernels[i].kind == kinds[i]);
    CHECK(p.kernels[i].decl == &b.kernels[i]);
  }
  for (std::size_t i = 0; i < 8; i += 2) CHECK(p.kernels[i].pool == p.kernels[i + 1].pool);
  const SourcePool& add = p.pools[p.kernels[0].pool];
  REQUIRE(add.wbu.size() == 1);
  CHECK(add.wbu[0].min_size == 1.5);
  CHECK(add.wbu[0].max_units == 200);
  REQUIRE(add.fsu.size() == 1);
  CHECK(add.fsu[0].after == 4000);
  CHECK(add.rpb.size() == 1);
  CHECK(add.split.empty());
  CHECK(add.doors.empty());
  const SourcePool& split = p.pools[p.kernels[2].pool];
  REQUIRE(split.split.size() == 1);
  CHECK(split.split[0].min_votes == 20);
  CHECK(split.wbu.empty());
  CHECK(p.pools[p.kernels[4].pool].wall_shift.at(0).sigma == 2.0);
  CHECK(p.pools[p.kernels[6].pool].doors.at(0).max_width == 2.0);
  // Tables in the enum order of likelihood.h: [predicted][observed], Free 0, Unknown 1, Wall 2.
  REQUIRE(p.tables.size() == 2);
  CHECK(p.tables[0].p[2][2] == 0.8);  // wall predicted, occupied observed
  CHECK(p.tables[1].p[2][1] == 0.1);  // lenient_lut row 0 (wall), column 1 (unknown)
  CHECK(p.tables[1].p[0][1] == 0.1);  // lenient_lut row 2 (free), column 1: equal to lut (indoor.ksm)
  CHECK(p.type_free_likelihood);      // so the tables do not depend on the types
  CHECK(p.prior.psi1 == Approx(std::exp(-1.0)));
  CHECK(p.prior.psi2 == Approx(std::exp(-1.0)));
  CHECK(p.prior.angle_tolerance == Approx(5.0 * 3.14159265358979323846 / 180.0));
  CHECK(p.semantic);
  CHECK(p.type_predicates == std::vector<std::int32_t>{gen::kPred_Room, gen::kPred_Corr, gen::kPred_Hall, gen::kPred_Other});
  CHECK(p.lenient == std::vector<bool>{true, false, true, false});
}

TEST_CASE("kernels are bound by their moves and their own sources, not by their names", "[indoor_kit]") {
  blk::Binding b = indoor_binding();
  // Renamed kernels keep their moves.
  b.kernels[0].name = "GROW";
  b.kernels[1].reverse = "GROW";
  KitPlan p = make_plan(b);
  CHECK(p.kernels[0].kind == KernelKind::Add);
  CHECK(p.kernels[1].kind == KernelKind::Remove);
  // A second birth / death pair draws from its own sources only.
  b.kernels.push_back({"SEED", "UNSEED", blk::Move::birth, {blk::detect::rpb(2.0)}, "kernel pair SEED / UNSEED"});
  b.kernels.push_back({"UNSEED", "SEED", blk::Move::death, {blk::detect::rpb(2.0)}, "kernel pair SEED / UNSEED"});
  // A self-reverse move as both halves of a pair.
  b.kernels.push_back({"SWAP", "UNSWAP", blk::Move::interchange, {blk::move::interchange()}, "kernel pair SWAP / UNSWAP"});
  b.kernels.push_back({"UNSWAP", "SWAP", blk::Move::interchange, {blk::move::interchange()}, "kernel pair SWAP / UNSWAP"});
  p = make_plan(b);
  REQUIRE(p.kernels.size() == 13);
  const SourcePool& seed = p.pools[p.kernels[9].pool];
  CHECK(p.kernels[9].kind == KernelKind::Add);
  CHECK(p.kernels[10].kind == KernelKind::Remove);
  CHECK(p.kernels[9].pool == p.kernels[10].pool);
  CHECK(p.kernels[9].pool != p.kernels[0].pool);
  CHECK(seed.wbu.empty());
  CHECK(seed.fsu.empty());
  REQUIRE(seed.rpb.size() == 1);
  CHECK(seed.rpb[0].min_size == 2.0);
  CHECK(p.pools[p.kernels[0].pool].rpb.at(0).min_size == 1.0);
  CHECK(p.kernels[11].kind == KernelKind::Interchange);
  CHECK(p.kernels[12].kind == KernelKind::Interchange);
  CHECK(p.kernels[11].pool == p.kernels[12].pool);
}

TEST_CASE("lenient types are the likelihood's predicate ids; absent priors weigh nothing", "[indoor_kit]") {
  blk::Binding b = indoor_binding();
  b.likelihood.lenient_types = {gen::kPred_Corr, gen::kPred_Other};
  b.priors = {blk::overlap_penalty(2.0), blk::overlap_penalty(0.5)};
  const KitPlan p = make_plan(b);
  CHECK(p.lenient == std::vector<bool>{false, true, false, true});
  CHECK(p.prior.psi2 == Approx(std::exp(-2.5)));  // weights add up
  CHECK(std::log(p.prior.psi1) == Approx(0.0).margin(1e-12));  // no rect_penalty: no penalty
}
