// Variable elimination (junction tree) against brute force and enumeration: random
// knowledge bases, random networks with blocks and hard clauses, the table-top scenes
// and the indoor knowledge base on floor plans.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "runtime/mln/components.h"
#include "runtime/mln/elimination.h"
#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/maxwalksat.h"
#include "tests/mln/brute_force.h"
#include "tests/mln/floor_plan.h"
#include "tests/mln/indoor_kb.h"
#include "tests/mln/random_kb.h"
#include "tests/mln/scene.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;
using ksmc::tests::mln::brute_force;

namespace {

// Every component by elimination (no cost choice): marginals, log Z and a mode.
struct ElimResult {
  std::vector<double> marginals;
  std::vector<std::uint8_t> mode;
  double log_z = 0.0;
  std::int32_t width = 0;
};

ElimResult eliminate_all(const GroundNetwork& net) {
  ElimResult r;
  r.marginals.assign(static_cast<std::size_t>(net.num_atoms()), -1.0);
  r.mode.assign(static_cast<std::size_t>(net.num_atoms()), 0);
  r.log_z = net.constant();
  for (const auto& comp : split_components(net)) {
    const auto plan = plan_elimination(net, comp);
    r.width = std::max(r.width, plan.width);
    r.log_z += eliminate_component(net, comp, plan, r.marginals, &r.mode);
  }
  return r;
}

ExactOptions enumeration_only() {
  ExactOptions o;
  o.use_elimination = false;
  o.max_component_bits = 26;
  return o;
}

double max_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

// Compares elimination with enumeration on one network: marginals, log Z, mode weight.
void check_against_enumeration(const GroundNetwork& net, double tol = 1e-9) {
  const auto el = eliminate_all(net);
  const auto en = exact_inference(net, enumeration_only());
  CHECK(std::abs(el.log_z - en.log_z) < tol * std::max(1.0, std::abs(en.log_z)));
  CHECK(max_error(el.marginals, en.marginals) < tol);
  CHECK(net.feasible(el.mode));
  CHECK(std::abs(net.log_weight(el.mode) - exact_map(net, enumeration_only()).log_weight) < 1e-9);
}

// A random network: free atoms, some exactly-one blocks, soft clauses of both signs,
// some hard clauses (may be infeasible).
GroundNetwork random_network(std::mt19937_64& rng, int atoms) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  GroundNetwork net;
  net.add_atoms(atoms);
  int a = 0;
  while (a + 3 <= atoms && uni(0, 2) == 0) {
    const int k = uni(2, 4);
    if (a + k > atoms) break;
    std::vector<AtomId> blk;
    for (int j = 0; j < k; ++j) blk.push_back(a + j);
    net.add_exactly_one(blk);
    a += k;
  }
  const int clauses = uni(atoms / 2, atoms * 2);
  std::uniform_real_distribution<double> w(-2.5, 3.0);
  for (int c = 0; c < clauses; ++c) {
    std::vector<Lit> lits;
    const int len = uni(1, 4);
    // mostly local clauses (sparse, low width), a few long-range ones
    const int base = uni(0, atoms - 1);
    for (int l = 0; l < len; ++l) {
      const int at = uni(0, 5) == 0 ? uni(0, atoms - 1) : std::clamp(base + uni(-3, 3), 0, atoms - 1);
      lits.push_back(make_lit(at, uni(0, 1) == 1));
    }
    if (uni(0, 7) == 0) net.add_hard_clause(lits);
    else net.add_clause(lits, w(rng));
  }
  net.add_constant(0.5);
  return net;
}

}  // namespace

TEST_CASE("elimination equals brute force on 400 random knowledge bases", "[mln][elimination][property]") {
  std::mt19937_64 rng(77001);
  int feasible = 0, with_blocks = 0;
  for (int trial = 0; trial < 400; ++trial) {
    auto kb = ksmc::tests::mln::make_random_kb(rng);
    INFO("trial " << trial);
    const auto ref = brute_force(kb.program, kb.domain, *kb.evidence);
    if (!ref.feasible) continue;
    ++feasible;
    const auto g = ground(kb.program, kb.domain, *kb.evidence);
    if (g.network.num_blocks() > 0) ++with_blocks;
    const auto el = eliminate_all(g.network);
    InferenceResult r;
    r.marginals = el.marginals;
    CHECK(std::abs(el.log_z - ref.log_z) < 1e-9);
    for (std::int64_t q = 0; q < g.index.num_query_atoms; ++q) {
      std::int32_t p = 0;
      for (std::size_t i = 0; i < g.index.offset.size(); ++i)
        if (g.index.offset[i] >= 0 && g.index.offset[i] <= q) p = static_cast<std::int32_t>(i);
      INFO(g.atom_name(q));
      CHECK(std::abs(g.marginal(r, q) - ref.at(p, q - g.index.offset[p])) < 1e-9);
    }
    CHECK(g.network.feasible(el.mode));
    CHECK(std::abs(g.network.log_weight(el.mode) - exact_map(g.network).log_weight) < 1e-9);
  }
  CHECK(feasible >= 200);
  CHECK(with_blocks >= 10);
}

TEST_CASE("elimination equals enumeration on 300 random networks with blocks and hard clauses",
          "[mln][elimination][property]") {
  std::mt19937_64 rng(424242);
  int checked = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto net = random_network(rng, 6 + trial % 13);
    INFO("trial " << trial);
    bool infeasible = false;
    try {
      exact_inference(net, enumeration_only());
    } catch (const MlnError&) {
      infeasible = true;
    }
    if (infeasible) {
      CHECK_THROWS_WITH(eliminate_all(net), Catch::Contains("no state satisfies the hard constraints"));
      ++refused;
      continue;
    }
    check_against_enumeration(net);
    ++checked;
  }
  CHECK(checked >= 150);
  WARN("random networks: " << checked << " matched enumeration, " << refused << " infeasible refused by both");
}

TEST_CASE("clause probabilities (expected clause counts): enumeration and elimination equal brute force",
          "[mln][elimination][clause_prob]") {
  std::mt19937_64 rng(777);
  int checked = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const auto net = random_network(rng, 6 + trial % 9);
    INFO("trial " << trial);
    // Brute force over all 2^n states (log_weight is -inf for infeasible ones).
    const auto n = net.num_atoms();
    std::vector<double> sat(static_cast<std::size_t>(net.num_clauses()), 0.0);
    std::vector<std::uint8_t> x(static_cast<std::size_t>(n));
    std::vector<double> lw;
    for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      for (AtomId a = 0; a < n; ++a) x[a] = (mask >> a) & 1;
      lw.push_back(net.log_weight(x));
    }
    const double mx = *std::max_element(lw.begin(), lw.end());
    if (!std::isfinite(mx)) continue;  // infeasible
    double z = 0.0;
    for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      const double p = std::exp(lw[mask] - mx);
      if (p == 0.0) continue;
      z += p;
      for (AtomId a = 0; a < n; ++a) x[a] = (mask >> a) & 1;
      for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
        bool s = false;
        for (Lit l : net.clause(c)) s = s || lit_true(l, x[lit_atom(l)]);
        if (s) sat[c] += p;
      }
    }
    for (double& v : sat) v /= z;
    std::vector<double> by_enum;
    const auto r = exact_clause_probabilities(net, by_enum, enumeration_only());
    CHECK(std::abs(r.log_z - (mx + std::log(z))) < 1e-9);
    std::vector<double> by_elim(sat.size(), -1.0), marg(static_cast<std::size_t>(n), 0.0);
    for (const auto& comp : split_components(net))
      eliminate_component(net, comp, plan_elimination(net, comp), marg, nullptr, nullptr, &by_elim);
    for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
      INFO("clause " << c);
      CHECK(std::abs(by_enum[c] - sat[c]) < 1e-9);
      CHECK(std::abs(by_elim[c] - sat[c]) < 1e-9);
    }
    ++checked;
  }
  CHECK(checked >= 60);
}

TEST_CASE("elimination equals enumeration on the table-top scenes", "[mln][elimination][tabletop]") {
  ksmc::tests::mln::TabletopKb kb;
  for (const char* name : {"scene3.db", "scene7.db", "scene20.db", "scene100.db"}) {
    INFO(name);
    const auto s = ksmc::tests::mln::data_scene(kb.program, name);
    check_against_enumeration(ground(kb.program, s.domain, *s.evidence).network);
  }
}

TEST_CASE("indoor KB: elimination equals enumeration on small plans", "[mln][elimination][indoor]") {
  ksmc::tests::mln::IndoorKb kb;
  for (const auto& plan : {ksmc::tests::mln::wing_plan(5), ksmc::tests::mln::wing_plan(6),
                           ksmc::tests::mln::grid_plan(2, 3)}) {
    INFO(plan.db());
    const auto s = ksmc::tests::mln::scene_from_text(kb.program, plan.db(), "plan.db");
    check_against_enumeration(ground(kb.program, s.domain, *s.evidence).network);
  }
}

TEST_CASE("indoor KB on a 60-unit plan: auto picks elimination and is consistent", "[mln][elimination][indoor]") {
  ksmc::tests::mln::IndoorKb kb;
  const auto plan = ksmc::tests::mln::wing_plan(60);
  const auto s = ksmc::tests::mln::scene_from_text(kb.program, plan.db(), "wing60.db");
  const auto g = ground(kb.program, s.domain, *s.evidence);
  InferenceOptions opt;
  opt.method = Method::Auto;
  const auto r = infer(g.network, opt);
  INFO(r.method);
  CHECK(r.method.rfind("exact:", 0) == 0);
  CHECK(r.method.find("elim 1") != std::string::npos);
  CHECK(r.log_z_exact);
  // Blocks sum to one, SaLe is symmetric, a corridor segment is a corridor.
  for (std::int32_t u = 0; u < 60; ++u) {
    const std::int32_t a[] = {u};
    double s = 0.0;
    for (auto p : {kb.room, kb.corr, kb.hall, kb.other}) s += g.marginal(r, p, a);
    CHECK(s == Approx(1.0).margin(1e-9));
  }
  for (const auto& [a, b] : plan.adjacent) {
    const std::int32_t ab[] = {a, b}, ba[] = {b, a};
    CHECK(std::abs(g.marginal(r, kb.sale, ab) - g.marginal(r, kb.sale, ba)) < 1e-12);
  }
  const std::int32_t c0[] = {0};
  CHECK(g.marginal(r, kb.corr, c0) > 0.5);
  // Exact MAP by max-product is feasible and at least as good as MaxWalkSAT's.
  const auto map = exact_map(g.network);
  CHECK(map.feasible);
  CHECK(map.log_weight >= max_walksat(g.network).log_weight - 1e-9);
}
