// Weight learning: weights of a known MLN recovered from worlds sampled exactly from it,
// by pseudo-likelihood and by the conditional likelihood (exact gradient, and sampled
// expectations where exact inference does not apply); bad training worlds refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/weight_learning.h"
#include "tests/mln/indoor_kb.h"

using namespace ksmc::runtime::mln;

namespace {

struct KnownMln {
  Program program;
  Domain domain;
  std::vector<double> truth{-1.0, 1.5, 2.0, 1.0};
  std::int32_t p = 0, q = 0, r = 0;
  explicit KnownMln(int constants = 5) {
    const auto t = program.add_type("t");
    p = program.add_predicate({"P", {t}, true, false, -1});
    q = program.add_predicate({"Q", {t}, true, false, -1});
    r = program.add_predicate({"R", {t}, false, false, -1});
    auto clause = [&](const char* name, int nvars, std::vector<Literal> lits, double w) {
      Clause c;
      c.name = name;
      c.text = name;
      c.loc = {"known.ksm", static_cast<std::int32_t>(program.clauses.size()) + 1};
      for (int v = 0; v < nvars; ++v) c.variables.push_back({v == 0 ? "x" : "y", t, false});
      c.literals = std::move(lits);
      c.weight = w;
      program.add_clause(c);
    };
    clause("P(x)", 1, {{p, false, {Term::var(0)}}}, truth[0]);
    clause("P(x) => Q(x)", 1, {{p, true, {Term::var(0)}}, {q, false, {Term::var(0)}}}, truth[1]);
    clause("R(x) => P(x)", 1, {{r, true, {Term::var(0)}}, {p, false, {Term::var(0)}}}, truth[2]);
    clause("Q(x) => Q(y)", 2, {{q, true, {Term::var(0)}}, {q, false, {Term::var(1)}}}, truth[3]);
    domain.resize(1);
    for (int i = 0; i < constants; ++i) domain.add(t, std::string(1, static_cast<char>('A' + i)));
  }
};

// `n` worlds drawn exactly from the network's distribution (all 2^atoms states enumerated).
std::vector<std::vector<std::uint8_t>> sample_worlds(const GroundNetwork& net, int n, std::uint64_t seed) {
  const auto atoms = net.num_atoms();
  std::vector<double> cdf;
  std::vector<std::uint8_t> x(static_cast<std::size_t>(atoms));
  double mx = -1e300;
  std::vector<double> lw;
  for (std::uint32_t s = 0; s < (1u << atoms); ++s) {
    for (std::int32_t a = 0; a < atoms; ++a) x[a] = (s >> a) & 1;
    lw.push_back(net.log_weight(x));
    mx = std::max(mx, lw.back());
  }
  double acc = 0.0;
  for (double l : lw) cdf.push_back(acc += std::exp(l - mx));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, acc);
  std::vector<std::vector<std::uint8_t>> out;
  for (int i = 0; i < n; ++i) {
    const auto s = static_cast<std::uint32_t>(std::lower_bound(cdf.begin(), cdf.end(), u(rng)) - cdf.begin());
    for (std::int32_t a = 0; a < atoms; ++a) x[a] = (s >> a) & 1;
    out.push_back(x);
  }
  return out;
}

TrainingSet known_training_set(KnownMln& kb, int worlds) {
  Evidence ev(kb.program, kb.domain);
  for (std::int32_t c : {0, 2, 3}) {
    const std::int32_t args[] = {c};
    ev.set(kb.r, args, true);
  }
  TrainingSet ts;
  ts.network = ground(kb.program, kb.domain, ev).network;
  REQUIRE(ts.network.num_atoms() == 2 * kb.domain.size(0));
  ts.worlds = sample_worlds(ts.network, worlds, 2024);
  return ts;
}

WeightTying one_param_per_clause(const Program& program) {
  WeightTying t;
  t.num_params = static_cast<std::int32_t>(program.clauses.size());
  for (std::size_t c = 0; c < program.clauses.size(); ++c) {
    t.param_of_clause.push_back(static_cast<std::int32_t>(c));
    t.scale_of_clause.push_back(1.0);
  }
  return t;
}

}  // namespace

TEST_CASE("weight learning recovers a known MLN's weights from 2,000 sampled worlds", "[mln][learn]") {
  KnownMln kb;
  const TrainingSet ts[] = {known_training_set(kb, 2000)};
  const auto tying = one_param_per_clause(kb.program);
  for (auto objective : {Objective::PseudoLikelihood, Objective::ConditionalLikelihood}) {
    LearnOptions opt;
    opt.objective = objective;
    const auto r = learn_weights(ts, tying, {}, opt);
    INFO((objective == Objective::PseudoLikelihood ? "pseudo-likelihood" : "conditional likelihood")
         << ": learned " << r.params[0] << " " << r.params[1] << " " << r.params[2] << " " << r.params[3] << " in "
         << r.iterations << " iterations");
    CHECK(r.converged);
    for (std::size_t j = 0; j < kb.truth.size(); ++j) CHECK(std::abs(r.params[j] - kb.truth[j]) < 0.1 * std::abs(kb.truth[j]));
    WARN((objective == Objective::PseudoLikelihood ? "PLL" : "CLL") << " weights " << r.params[0] << ", "
         << r.params[1] << ", " << r.params[2] << ", " << r.params[3] << " (truth -1, 1.5, 2, 1), " << r.iterations
         << " iterations");
  }
}

TEST_CASE("weight learning: a strong prior shrinks, tied clauses share a weight, bad worlds are refused",
          "[mln][learn]") {
  KnownMln kb;
  const TrainingSet ts[] = {known_training_set(kb, 300)};
  auto tying = one_param_per_clause(kb.program);
  const auto free = learn_weights(ts, tying, {});
  LearnOptions strong;
  strong.prior_sigma = 0.01;
  const auto shrunk = learn_weights(ts, tying, {}, strong);
  for (std::size_t j = 0; j < free.params.size(); ++j) CHECK(std::abs(shrunk.params[j]) < 0.5 * std::abs(free.params[j]));
  // Clauses 1 and 2 tied to one parameter: it lands between their separate estimates.
  tying.num_params = 3;
  tying.param_of_clause = {0, 1, 1, 2};
  const auto tied = learn_weights(ts, tying, {});
  CHECK(tied.params[1] > std::min(free.params[1], free.params[2]) - 1e-6);
  CHECK(tied.params[1] < std::max(free.params[1], free.params[2]) + 1e-6);
  // A world breaking an exactly-one block / hard clause.
  TrainingSet bad;
  bad.network.add_atoms(2);
  const AtomId blk[] = {0, 1};
  bad.network.add_exactly_one(blk);
  bad.worlds = {{1, 0}, {1, 1}};
  const TrainingSet bads[] = {std::move(bad)};
  WeightTying none;
  CHECK_THROWS_WITH(learn_weights(bads, none, {}), "training set 1, world 2: breaks an exactly-one block");
}

TEST_CASE("conditional likelihood: the exact gradient equals central finite differences", "[mln][learn][cll]") {
  // The indoor rule base on 6 units: one component that exact inference solves by
  // variable elimination (blocks, hard clauses, clauses of up to 4 literals).
  ksmc::tests::mln::IndoorKb kb;
  const std::string scene =
      "CoLi(U0)\nMulDoor(U0)\nRoLi(U1)\nRoLi(U2)\nHaLi(U3)\nMulDoor(U3)\nRoLi(U5)\n"
      "Adj(U0, U1)\nAdj(U1, U0)\nAdj(U0, U2)\nAdj(U2, U0)\nAdj(U0, U3)\nAdj(U3, U0)\nAdj(U1, U2)\nAdj(U2, U1)\n"
      "Adj(U3, U4)\nAdj(U4, U3)\nAdj(U4, U5)\nAdj(U5, U4)\nAdj(U2, U5)\nAdj(U5, U2)\n";
  Domain d;
  collect_db_constants(scene, "plan.db", kb.program, d);
  Evidence ev(kb.program, d);
  parse_db(scene, "plan.db", kb.program, d, ev);
  TrainingSet ts;
  ts.network = ground(kb.program, d, ev).network;
  REQUIRE(exact_inference(ts.network).method.find("elim") != std::string::npos);
  // Two feasible worlds: the most probable state, and the one of the opposite weights.
  ts.worlds.push_back(exact_map(ts.network).state);
  Program flipped = kb.program;
  for (auto& c : flipped.clauses) c.weight = -c.weight;
  ts.worlds.push_back(exact_map(ground(flipped, d, ev).network).state);
  REQUIRE(ts.worlds[0] != ts.worlds[1]);
  // A parameter per soft rule, rules i5 and i6 tied with scale 0.5 each.
  WeightTying tying;
  for (const auto& c : kb.program.clauses) {
    tying.param_of_clause.push_back(c.hard ? -1 : tying.num_params);
    tying.scale_of_clause.push_back(1.0);
    if (!c.hard) ++tying.num_params;
  }
  tying.param_of_clause[4] = tying.param_of_clause[3];
  tying.scale_of_clause[3] = tying.scale_of_clause[4] = 0.5;
  const TrainingSet sets[] = {std::move(ts)};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.5);
  std::vector<double> w(static_cast<std::size_t>(tying.num_params));
  for (double& x : w) x = u(rng);
  w[5] = 0.0;  // a zero weight keeps its clause in the gradient
  std::vector<double> grad, scratch;
  conditional_log_likelihood(sets, tying, w, grad);
  constexpr double h = 1e-5;
  for (std::size_t j = 0; j < w.size(); ++j) {
    INFO("parameter " << j);
    auto wp = w;
    wp[j] = w[j] + h;
    const double up = conditional_log_likelihood(sets, tying, wp, scratch);
    wp[j] = w[j] - h;
    const double down = conditional_log_likelihood(sets, tying, wp, scratch);
    const double fd = (up - down) / (2 * h);
    CHECK(std::abs(grad[j] - fd) < 1e-6 * std::max(1.0, std::abs(fd)));
  }
}

TEST_CASE("conditional likelihood: sampled expectations agree with the exact gradient", "[mln][learn][cll]") {
  // Forced MC-SAT expectations on a network exact inference solves: within 0.15 (absolute,
  // log-odds) of the exact-gradient weights.
  KnownMln kb;
  const TrainingSet ts[] = {known_training_set(kb, 2000)};
  const auto tying = one_param_per_clause(kb.program);
  LearnOptions exact;
  exact.objective = Objective::ConditionalLikelihood;
  const auto e = learn_weights(ts, tying, {}, exact);
  CHECK(e.gradient.rfind("exact gradient (exact:enum", 0) == 0);
  CHECK_FALSE(e.sampled);
  LearnOptions sampled = exact;
  sampled.expectations = Expectations::Sampled;
  const auto s = learn_weights(ts, tying, {}, sampled);
  CHECK(s.sampled);
  CHECK(s.gradient == "sampled expectations (MC-SAT, 1000 samples, 100 diagonal Newton iterations)");
  for (std::size_t j = 0; j < kb.truth.size(); ++j) CHECK(std::abs(s.params[j] - e.params[j]) < 0.15);
  WARN("CLL exact " << e.params[0] << ", " << e.params[1] << ", " << e.params[2] << ", " << e.params[3]
       << "; sampled " << s.params[0] << ", " << s.params[1] << ", " << s.params[2] << ", " << s.params[3]);
  // Same seed, same weights.
  CHECK(learn_weights(ts, tying, {}, sampled).params == s.params);
}

TEST_CASE("conditional likelihood: a network over the exact limit learns by sampled expectations",
          "[mln][learn][cll]") {
  // 6 constants: one component of 12 free atoms, above a 10-bit limit without elimination.
  // Weights within 10 % of the truth, from 2,000 worlds sampled exactly.
  KnownMln kb(6);
  const TrainingSet ts[] = {known_training_set(kb, 2000)};
  const auto tying = one_param_per_clause(kb.program);
  LearnOptions opt;
  opt.objective = Objective::ConditionalLikelihood;
  opt.exact.max_component_bits = 10;
  opt.exact.use_elimination = false;
  const auto r = learn_weights(ts, tying, {}, opt);
  CHECK(r.sampled);
  CHECK(r.too_large_set == 0);
  CHECK(r.too_large_reason ==
        "a component of 12 free atoms (12 bits of state) that neither enumeration nor variable elimination fits");
  CHECK(std::isnan(r.objective));
  for (std::size_t j = 0; j < kb.truth.size(); ++j) CHECK(std::abs(r.params[j] - kb.truth[j]) < 0.1 * std::abs(kb.truth[j]));
  WARN("CLL sampled (12 atoms over the limit) " << r.params[0] << ", " << r.params[1] << ", " << r.params[2] << ", "
       << r.params[3] << " (truth -1, 1.5, 2, 1)");
  opt.expectations = Expectations::Exact;
  CHECK_THROWS_WITH(learn_weights(ts, tying, {}, opt), Catch::Contains("training set 1: exact inference: a connected component has 12 free atoms"));
}
