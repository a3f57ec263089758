// Incremental re-inference: after evidence changes, the result equals a fresh auto
// inference on the re-grounded network, and only changed components are re-solved.
#include <catch2/catch.hpp>

#include <random>

#include "runtime/mln/error.h"
#include "runtime/mln/incremental.h"
#include "tests/mln/floor_plan.h"
#include "tests/mln/indoor_kb.h"
#include "tests/mln/random_kb.h"
#include "tests/mln/scene.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;

namespace {

// Fresh inference on the incremental engine's current evidence; compares every query atom.
void check_fresh(const Program& program, const Domain& domain, const IncrementalInference& inc) {
  const auto g = ground(program, domain, inc.evidence());
  InferenceOptions opt;
  const auto fresh = infer(g.network, opt);
  CHECK(std::abs(fresh.log_z - inc.result().log_z) < 1e-9 * std::max(1.0, std::abs(fresh.log_z)));
  double err = 0.0;
  for (std::int64_t q = 0; q < g.index.num_query_atoms; ++q)
    err = std::max(err, std::abs(g.marginal(fresh, q) - inc.grounding().marginal(inc.result(), q)));
  CHECK(err < 1e-9);
}

}  // namespace

TEST_CASE("incremental: table-top scene, one object's evidence changed", "[mln][incremental]") {
  ksmc::tests::mln::TabletopKb kb;
  const auto scene = ksmc::tests::mln::data_scene(kb.program, "scene20.db");
  const Domain& d = scene.domain;
  const Evidence& ev = *scene.evidence;
  IncrementalInference inc(kb.program, d, ev);
  check_fresh(kb.program, d, inc);
  const std::int32_t components = inc.stats().components;
  CHECK(inc.stats().reused == 0);
  // Object 3 becomes unstable (flip its stable evidence).
  const std::int32_t args[] = {3};
  const std::int8_t old = ev.get(kb.stable, args);
  const EvidenceChange ch[] = {{kb.stable, {3}, static_cast<std::int8_t>(old == 1 ? 0 : 1)}};
  inc.update(ch);
  check_fresh(kb.program, d, inc);
  INFO(inc.result().method);
  CHECK(inc.stats().solved >= 1);
  CHECK(inc.stats().solved <= 3);
  CHECK(inc.stats().reused + inc.stats().solved == inc.stats().components);
  CHECK(inc.stats().reused >= components - 3);
  // Changing it back re-solves the same few components again, the rest stays.
  const EvidenceChange back[] = {{kb.stable, {3}, old}};
  inc.update(back);
  check_fresh(kb.program, d, inc);
  CHECK(inc.stats().solved <= 3);
}

TEST_CASE("incremental: indoor 60-unit plan, one unit moved, the elimination plan is reused",
          "[mln][incremental][indoor]") {
  ksmc::tests::mln::IndoorKb kb;
  const auto scene = ksmc::tests::mln::scene_from_text(kb.program, ksmc::tests::mln::wing_plan(60).db(), "wing60.db");
  const Domain& d = scene.domain;
  const Evidence& ev = *scene.evidence;
  IncrementalInference inc(kb.program, d, ev);
  check_fresh(kb.program, d, inc);
  // Unit U12 (a room) now looks like a hall.
  const std::int32_t u12 = *d.find(kb.unit, "U12"), u1 = *d.find(kb.unit, "U1"), u8 = *d.find(kb.unit, "U8");
  const std::int32_t args[] = {u12};
  REQUIRE(ev.get(kb.roli, args) == 1);
  const EvidenceChange moved[] = {{kb.roli, {u12}, 0}, {kb.hali, {u12}, 1}};
  inc.update(moved);
  INFO(inc.result().method);
  check_fresh(kb.program, d, inc);
  CHECK(inc.stats().plans_reused == 1);
  // A new adjacency changes the variables (a SaLe pair becomes free): planned anew.
  const EvidenceChange adj[] = {{kb.adj, {u1, u8}, 1}, {kb.adj, {u8, u1}, 1}};
  inc.update(adj);
  check_fresh(kb.program, d, inc);
  CHECK(inc.stats().plans_reused == 0);
}

TEST_CASE("incremental: random knowledge bases under random evidence changes", "[mln][incremental][property]") {
  std::mt19937_64 rng(99);
  int updates = 0;
  for (int trial = 0; trial < 60; ++trial) {
    auto kb = ksmc::tests::mln::make_random_kb(rng);
    INFO("trial " << trial);
    std::unique_ptr<IncrementalInference> inc;
    try {
      inc = std::make_unique<IncrementalInference>(kb.program, kb.domain, *kb.evidence);
    } catch (const MlnError&) {
      continue;  // unsatisfiable under this evidence
    }
    for (int step = 0; step < 5; ++step) {
      std::vector<EvidenceChange> changes;
      for (std::int32_t p = 0; p < static_cast<std::int32_t>(kb.program.predicates.size()); ++p) {
        const auto& pred = kb.program.predicates[p];
        if (pred.query || std::uniform_int_distribution<int>(0, 1)(rng) == 0) continue;
        std::vector<std::int32_t> args;
        for (auto t : pred.arg_types) args.push_back(std::uniform_int_distribution<int>(0, kb.domain.size(t) - 1)(rng));
        changes.push_back({p, args, static_cast<std::int8_t>(std::uniform_int_distribution<int>(0, 1)(rng))});
      }
      try {
        inc->update(changes);
      } catch (const MlnError&) {
        break;  // the change made a hard rule unsatisfiable: the engine is not reusable
      }
      check_fresh(kb.program, kb.domain, *inc);
      ++updates;
    }
  }
  CHECK(updates >= 50);
}

TEST_CASE("incremental: bad changes are refused with a message", "[mln][incremental]") {
  ksmc::tests::mln::IndoorKb kb;
  const auto scene = ksmc::tests::mln::scene_from_text(kb.program, ksmc::tests::mln::wing_plan(5).db(), "wing5.db");
  const Domain& d = scene.domain;
  const Evidence& ev = *scene.evidence;
  IncrementalInference inc(kb.program, d, ev);
  const EvidenceChange arity[] = {{kb.adj, {1}, 1}};
  CHECK_THROWS_WITH(inc.update(arity), "incremental inference: Adj takes 2 arguments, the change gives 1");
  const EvidenceChange range[] = {{kb.roli, {9}, 1}};
  CHECK_THROWS_WITH(inc.update(range), "incremental inference: argument 1 of RoLi is not a constant of its type");
  const EvidenceChange unknown[] = {{kb.roli, {1}, Evidence::kUnknown}};
  CHECK_THROWS_WITH(inc.update(unknown),
                    "incremental inference: evidence atom of RoLi cannot be unknown (closed world)");
  InferenceOptions gibbs;
  gibbs.method = Method::Gibbs;
  CHECK_THROWS_WITH(IncrementalInference(kb.program, d, ev, gibbs),
                    "incremental inference needs the exact or auto method");
}
