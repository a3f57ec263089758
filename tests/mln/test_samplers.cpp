// Gibbs, MC-SAT and MaxWalkSAT against exact inference on several networks; every
// sample is checked against the hard clauses and blocks.
#include <catch2/catch.hpp>

#include <random>
#include <sstream>

#include "runtime/mln/components.h"
#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/gibbs.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/maxwalksat.h"
#include "runtime/mln/mcsat.h"
#include "tests/mln/network_fixtures.h"
#include "tests/mln/random_kb.h"

using namespace ksmc::runtime::mln;
using ksmc::tests::mln::enumerate_mode;

namespace {

double max_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

struct Case {
  std::string name;
  GroundNetwork net;
};

std::vector<Case> sampler_cases() {
  std::vector<Case> cases;
  cases.push_back({"mixed blocks+hard", ksmc::tests::mln::mixed_network()});
  cases.push_back({"hard equivalences", ksmc::tests::mln::equivalence_network()});
  // Random soft knowledge bases (with blocks sometimes) and a few with hard clauses
  // that leave the space connected under single moves (checked: both samplers agree).
  std::mt19937_64 rng(77);
  int made = 0;
  while (made < 6) {
    auto kb = ksmc::tests::mln::make_random_kb(rng, 10);
    for (auto& c : kb.program.clauses) c.hard = false, c.weight = c.weight == 0.0 ? 1.0 : c.weight;
    auto g = ground(kb.program, kb.domain, *kb.evidence);
    if (g.network.num_atoms() < 4) continue;
    std::size_t largest = 0;  // want coupled atoms, not independent ones
    for (const auto& comp : split_components(g.network)) largest = std::max(largest, comp.atoms.size());
    if (largest < 3) continue;
    cases.push_back({"random soft KB " + std::to_string(made), std::move(g.network)});
    ++made;
  }
  return cases;
}

}  // namespace

TEST_CASE("Gibbs and MC-SAT marginals within 0.02 of exact; no sample violates a hard constraint",
          "[mln][gibbs][mcsat]") {
  std::ostringstream table;
  table << "network                 atoms  gibbs_err  mcsat_err\n";
  for (const auto& cs : sampler_cases()) {
    INFO(cs.name);
    const auto exact = exact_inference(cs.net);
    std::int64_t bad = 0, seen = 0;
    auto check = [&](std::span<const std::uint8_t> s) {
      ++seen;
      if (!cs.net.feasible(s)) ++bad;
    };
    GibbsOptions go;
    go.samples = 20000;
    go.seed = 11;
    go.on_sample = check;
    const auto gibbs = gibbs_sampling(cs.net, go);
    McSatOptions mo;
    mo.samples = 20000;
    mo.seed = 12;
    mo.on_sample = check;
    const auto mcsat = mc_sat(cs.net, mo);
    CHECK(seen == 40000);
    CHECK(bad == 0);
    const double eg = max_error(gibbs.marginals, exact.marginals);
    const double em = max_error(mcsat.marginals, exact.marginals);
    CHECK(eg < 0.02);
    CHECK(em < 0.02);
    char line[128];
    std::snprintf(line, sizeof line, "%-22s %6d %10.4f %10.4f\n", cs.name.c_str(), cs.net.num_atoms(), eg, em);
    table << line;
  }
  WARN(table.str());
}

TEST_CASE("samplers are deterministic for a seed", "[mln][gibbs][mcsat]") {
  const auto net = ksmc::tests::mln::mixed_network();
  GibbsOptions go;
  go.samples = 500;
  go.seed = 5;
  CHECK(gibbs_sampling(net, go).marginals == gibbs_sampling(net, go).marginals);
  McSatOptions mo;
  mo.samples = 500;
  mo.seed = 5;
  CHECK(mc_sat(net, mo).marginals == mc_sat(net, mo).marginals);
  McSatOptions other = mo;
  other.seed = 6;
  CHECK(mc_sat(net, mo).marginals != mc_sat(net, other).marginals);
  GibbsOptions gother = go;
  gother.seed = 6;
  CHECK(gibbs_sampling(net, go).marginals != gibbs_sampling(net, gother).marginals);
  MapOptions map;
  map.seed = 9;
  CHECK(max_walksat(net, map).state == max_walksat(net, map).state);
}

TEST_CASE("MC-SAT never violates hard clauses on random KBs with hard rules", "[mln][mcsat]") {
  std::mt19937_64 rng(99);
  int tested = 0;
  for (int trial = 0; trial < 60; ++trial) {
    auto kb = ksmc::tests::mln::make_random_kb(rng, 12);
    GroundNetwork net;
    try {
      net = ground(kb.program, kb.domain, *kb.evidence).network;
      exact_inference(net);  // skip unsatisfiable ones
    } catch (const MlnError&) {
      continue;
    }
    if (net.num_hard() == 0 && net.num_blocks() == 0) continue;
    ++tested;
    std::int64_t bad = 0;
    McSatOptions mo;
    mo.samples = 300;
    mo.seed = static_cast<std::uint64_t>(trial);
    mo.on_sample = [&](std::span<const std::uint8_t> s) { bad += net.feasible(s) ? 0 : 1; };
    mc_sat(net, mo);
    GibbsOptions go;
    go.samples = 300;
    go.seed = static_cast<std::uint64_t>(trial);
    go.on_sample = mo.on_sample;
    gibbs_sampling(net, go);
    CHECK(bad == 0);
  }
  CHECK(tested >= 15);
}

TEST_CASE("MAP by MaxWalkSAT equals the exact mode", "[mln][map]") {
  std::vector<GroundNetwork> nets;
  nets.push_back(ksmc::tests::mln::mixed_network());
  std::mt19937_64 rng(4242);
  while (nets.size() < 60) {
    auto kb = ksmc::tests::mln::make_random_kb(rng, 14);
    try {
      auto net = ground(kb.program, kb.domain, *kb.evidence).network;
      if (net.num_atoms() == 0) continue;
      exact_inference(net);
      nets.push_back(std::move(net));
    } catch (const MlnError&) {
    }
  }
  int unique = 0;
  for (std::size_t i = 0; i < nets.size(); ++i) {
    INFO("network " << i);
    const auto mode = enumerate_mode(nets[i]);
    if (!mode.unique) continue;
    ++unique;
    MapOptions opt;
    opt.seed = 3;
    const auto map = max_walksat(nets[i], opt);
    CHECK(map.feasible);
    CHECK(map.state == mode.state);
    CHECK(map.log_weight == Approx(mode.log_weight).margin(1e-9));
  }
  CHECK(unique >= 10);
}

TEST_CASE("unsatisfiable hard constraints are reported with the rule", "[mln][map]") {
  GroundNetwork net;
  net.set_origin_names({"r1 `a v b` (kb.ksm:3)", "r2 `!a` (kb.ksm:4)", "r3 `!b` (kb.ksm:5)"});
  net.add_atoms(2);
  const Lit ab[] = {make_lit(0, false), make_lit(1, false)};
  const Lit na[] = {make_lit(0, true)};
  const Lit nb[] = {make_lit(1, true)};
  net.add_hard_clause(ab, 0);
  net.add_hard_clause(na, 1);
  net.add_hard_clause(nb, 2);
  CHECK_THROWS_WITH(gibbs_sampling(net), Catch::Contains("no state satisfying the hard constraints found") &&
                                             Catch::Contains("kb.ksm:"));
  CHECK_THROWS_WITH(exact_inference(net), Catch::Contains("no state satisfies the hard constraints") &&
                                              Catch::Contains("r1 `a v b` (kb.ksm:3)"));
}
